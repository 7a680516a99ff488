// The hex8 element: rigid motions make no strain, forces are the energy's gradient, the patch
// test, and the critical step of a lumped cube.
#include <catch2/catch.hpp>

#include <cmath>

#include "dem/deformable/deformable_body.hpp"
#include "dem/deformable/hex8.hpp"
#include "dem/block_builder.hpp"
#include "dem/mesh.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;
using namespace cairn::dem;

namespace {

// a distorted (trilinear, non-parallelepiped) element
Corners distorted() {
    Corners c = box_corners(Vec3(1.0, 0.8, 1.2));
    c[6] += Vec3(0.1, 0.05, 0.08);
    c[1] += Vec3(0.04, -0.03, 0.0);
    c[4] += Vec3(-0.05, 0.02, 0.03);
    return c;
}

Mat83 rows(const Corners& c) {
    Mat83 x;
    for (int a = 0; a < 8; ++a) x.row(a) = c[a].transpose();
    return x;
}

const Lame kStone = lame(30e9, 0.2);

}  // namespace

TEST_CASE("a large rigid rotation and translation of a hex8 makes no strain and no force", "[dem][hex8]") {
    Corners c = distorted();
    Hex8Reference ref = hex8_reference(c);
    const Mat3 r = Eigen::AngleAxisd(2.0, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    Mat83 x;
    for (int a = 0; a < 8; ++a) x.row(a) = (r * c[a] + Vec3(5, -3, 2)).transpose();
    Mat83 f = Mat83::Zero();
    double w = hex8_internal_force(ref, kStone, x, f);
    // rounding of E = ½(FᵀF − I) for |F| ~ 1 is ~1e-16: energy ~E·V·1e-32, forces ~E·area·1e-16
    // ≈ 3e-6 N; a small-strain (linear) element would give forces ~E·area·θ ≈ 6e10 N here
    CHECK(std::abs(w) < 1e-9);
    CHECK(f.norm() < 1e-3);
}

TEST_CASE("hex8 internal forces are the gradient of the strain energy (central differences)", "[dem][hex8]") {
    Corners c = distorted();
    Hex8Reference ref = hex8_reference(c);
    Mat83 x = rows(c);
    // a finite deformation: 8 % stretch, shear and a rotation
    Mat3 a;
    a << 1.08, 0.05, 0.0, -0.03, 0.97, 0.04, 0.02, 0.0, 1.05;
    for (int i = 0; i < 8; ++i) x.row(i) = (Eigen::AngleAxisd(0.7, Vec3::UnitZ()) * (a * c[i])).transpose();
    x(6, 2) += 0.01;
    Mat83 f = Mat83::Zero();
    hex8_internal_force(ref, kStone, x, f);
    const double h = 1e-7;
    for (int i = 0; i < 8; ++i)
        for (int d = 0; d < 3; ++d) {
            Mat83 xp = x, xm = x, dummy = Mat83::Zero();
            xp(i, d) += h;
            xm(i, d) -= h;
            double fd = (hex8_internal_force(ref, kStone, xp, dummy) - hex8_internal_force(ref, kStone, xm, dummy)) / (2 * h);
            // central differences: truncation ~h²·W''' and rounding ~1e-16·W/h; with W ~ 1e8 J both
            // stay below 1e-6 of the force scale |f| ~ 1e9 N
            CHECK(f(i, d) == Approx(fd).margin(1e-6 * f.norm()));
        }
}

TEST_CASE("patch test: an affine deformation of a distorted mesh gives zero force at inner nodes", "[dem][hex8]") {
    Corners c = distorted();
    Mesh mesh = make_mesh(c, {2, 2, 2});
    const Material stone = test::stone();
    DeformableBody body(mesh, stone, MassScheme::lumped, 0.0, std::vector<char>(mesh.nodes.size(), 0));
    Mat3 a;
    a << 1.001, 0.0004, 0.0, 0.0002, 0.9995, 0.0003, 0.0, 0.0001, 1.0007;
    std::vector<Vec3> x, v(mesh.nodes.size(), Vec3::Zero()), f(mesh.nodes.size(), Vec3::Zero());
    for (const auto& p : mesh.nodes) x.push_back(a * p);
    body.add_internal_forces(x, v, f);
    // the centre node is interior: a uniform stress is in equilibrium element by element
    const int centre = mesh.node(1, 1, 1);
    double scale = 0.0;
    for (const auto& fi : f) scale = std::max(scale, fi.norm());
    REQUIRE(scale > 1e5);
    // rounding only: the interior sum cancels contributions of size `scale`
    CHECK(f[centre].norm() < 1e-9 * scale);
    // the total force on the block vanishes (self-equilibrated)
    Vec3 total = Vec3::Zero();
    for (const auto& fi : f) total += fi;
    CHECK(total.norm() < 1e-9 * scale);
}

TEST_CASE("critical step of a lumped hex8 cube is sqrt(2/3)·L/c_d", "[dem][hex8][timestep]") {
    const Material stone = test::stone();
    const double cd = std::sqrt((kStone.lambda + 2 * kStone.mu) / stone.density);
    REQUIRE(cd == Approx(3580.6).epsilon(1e-4));
    for (double l : {1.0, 0.25}) {
        Mesh mesh = make_mesh(box_corners(Vec3(l, l, l)), {1, 1, 1});
        DeformableBody body(mesh, stone, MassScheme::lumped, 0.0, std::vector<char>(8, 0));
        // docs/physics.md: the fully integrated lumped hex8 cube: Δt = √(2/3)·L/c_d exactly
        CHECK(2.0 / body.max_element_omega() == Approx(std::sqrt(2.0 / 3.0) * l / cd).epsilon(1e-9));
    }
}

TEST_CASE("a meshed side carries one regular grid of hitting points whose areas sum to the side's", "[dem][contact]") {
    Scene s;
    s.materials.push_back(test::stone());
    s.contact.scheme = ContactScheme::paper;
    s.contact.grid_spacing = 0.1;
    BlockDef d;
    d.name = "A";
    d.size = Vec3(1.0, 1.0, 1.0);
    d.corners = box_corners(d.size);
    d.model = BlockModel::deformable;
    d.mesh.divisions = {4, 4, 4};
    Block b = make_block(d, s);
    for (int side = 0; side < 6; ++side) {
        double area = 0.0;
        size_t points = 0;
        for (int f : b.mesh.side_grid[side]) {
            for (const auto& p : b.hits[f]) area += p.area;
            points += b.hits[f].size();
        }
        // 0.25 m faces at a 0.1 m spacing: 4 x 4 points each; shared edges kept once: 13 x 13
        CHECK(points == 13u * 13u);
        // the trapezoid weights of a uniform grid sum to the area exactly (rounding only)
        CHECK(area == Approx(1.0).epsilon(1e-12));
    }
}
