// The overlap scheme's force is the gradient of its stored energy U = ½kn∫d² dA: checked against
// central finite differences of U, for a polygon clipped by a target edge and for whole blocks
// (a block lying across the edge of its base, over an acute edge, a face tilted to its target).
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "dem/block_builder.hpp"
#include "dem/contact.hpp"
#include "dem/contact_overlap_edge.hpp"
#include "gradient_check.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;
using namespace cairn::dem;
using cairn::test::gradient_gap;
using cairn::test::show;
using cairn::test::Gap;

namespace {

// a hitting cell (a parallelogram below z = 0, tilted) moved by `shift`, clipped behind the
// plane z = 0 and inside the half plane x ≤ 0.3 (a target edge); kn = 1
struct CellLoad {
    double energy = 0.0;        // ½∫d² dA, J per unit kn
    Vec3 force = Vec3::Zero();  // the normal force along +z plus the edge forces
};
CellLoad cell_load(const Vec3& shift) {
    const Affine depth{Vec3(0, 0, -1), 0.0}, edge{Vec3(-1, 0, 0), 0.3};
    const Affine edge_tilted{Vec3(-0.2, -1.0, 0.0).normalized(), 0.35};   // a second edge, across
    ClipPolygon poly;
    poly.n = 4;
    auto at = [&](double x, double y) -> Vec3 { return Vec3(x, y, -0.004 + 0.01 * x - 0.006 * y) + shift; };
    poly.p = {at(-0.2, -0.3), at(-0.2, 0.3), at(0.5, 0.3), at(0.5, -0.3)};
    clip(poly, depth, 0);
    clip(poly, edge, 1);
    clip(poly, edge_tilted, 2);
    const OverlapIntegrals in = integrate_depth(poly, Vec3::Zero(), Vec3::UnitZ());
    CellLoad r;
    r.energy = 0.5 * in.d2;
    r.force = in.d1 * Vec3::UnitZ();
    for (int i = 0; i < poly.n; ++i) {
        const int k = int(poly.by[size_t(i)]) - 1;
        if (k == 1 || k == 2) r.force += edge_force(poly, i, Vec3::Zero(), Vec3::UnitZ(), k == 1 ? edge : edge_tilted, in.slope, 1.0).force;
    }
    return r;
}

// the paper's stone, kn = 3e7 N/m³, no shear (its fresh springs carry no energy anyway) and no
// damping: the stored energy is ½kn∫d² dA alone
Scene frictionless_scene() {
    Scene s = test::stone_scene(0.6);
    s.contact.scheme = ContactScheme::overlap;
    s.contact.ks = 0.0;
    return s;
}

// block A (1.0 × 0.4 × 0.3 m) lying 2 mm deep across the +x edge of B's top (z = 0, x = 0.5),
// overhanging it by 0.55 m, turned by q about its centre
Scene across_edge(const Quat& q, const Corners* base = nullptr) {
    Scene s = frictionless_scene();
    add_box(s, "A", Vec3(1.0, 0.4, 0.3), Vec3(0.55, 0.05, 0.15 - 0.002), false, q);
    add_box(s, "B", Vec3(1.0, 1.0, 0.5), Vec3(0.0, 0.0, -0.25), true);
    if (base) {
        s.blocks[1].shape = Shape::hexahedron;
        s.blocks[1].corners = *base;
        s.blocks[1].position = Vec3::Zero();
    }
    return s;
}

// a pose with nothing square to B: turned 0.2 rad about z, tilted 3 mrad about a skew axis
Quat skew() {
    return Quat(Eigen::AngleAxisd(3e-3, Vec3(0.3, 1.0, 0.2).normalized())) * Quat(Eigen::AngleAxisd(0.2, Vec3::UnitZ()));
}


}  // namespace

TEST_CASE("a cell ending on target edges: the normal force plus the edge forces is −∇U", "[dem][contact]") {
    // U is piecewise polynomial in the shift; a central difference of step 1e-7 m errs by
    // (h/d)²·|U'''|/6 ~ 1e-10 of the force and by rounding 1e-16·U/h ~ 1e-11: 1e-7 bounds both
    const double h = 1e-7;
    const CellLoad at = cell_load(Vec3::Zero());
    Vec3 fd;
    for (int k = 0; k < 3; ++k)
        fd[k] = -(cell_load(h * Vec3::Unit(k)).energy - cell_load(-h * Vec3::Unit(k)).energy) / (2.0 * h);
    INFO("force " << at.force.transpose() << ", −∇U " << fd.transpose());
    // the edge forces are ½∫d² ds ≈ 1e-6 along x and y against ∫d dA ≈ 1e-3 along z: without them
    // the gap would be 1e-3 of the force
    REQUIRE(std::abs(at.force.x()) > 1e-4 * at.force.norm());
    CHECK((at.force - fd).norm() < 1e-7 * at.force.norm());
}

TEST_CASE("a block lying across the edge of its base is pushed by −∇U", "[dem][contact]") {
    // A tilted 3 mrad about x: its depth runs from 1.4 to 2.6 mm along B's edge. Steps 1e-8 m
    // and 1e-8 rad against a 2 mm depth: truncation (h/d)² ~ 1e-11 and rounding 1e-16·U/(h·F)
    // ~ 1e-10 of the force (lever 0.5 m for the moment); 1e-7 bounds both. Without the edge force
    // the gap is ½kn∫d² ds / (kn∫d dA) ~ d/(2·0.45 m) ≈ 2e-3 (the force along x, and its moment)
    const Gap g = gradient_gap(across_edge(Quat(Eigen::AngleAxisd(3e-3, Vec3::UnitX()))), 1e-8, 1e-8, 0.5);
    INFO(show(g));
    REQUIRE(g.f.x() > 1e-3 * g.f.z());   // the edge force pushes A off the edge
    CHECK(g.force < 1e-7);
    CHECK(g.moment < 1e-7);
}

TEST_CASE("a block across the edge of its base in a skew pose is pushed by −∇U", "[dem][contact]") {
    // nothing square: A's bottom also faces B's +x side (the region splits on the bisector), and
    // A's long sides, turned 0.2 rad, run across B's +x side while 2 mm below B's top; every
    // boundary fixed to B with depth has its edge force, and where the region ends on one the
    // couple of the faces' tilt no longer cancels (docs/dem.md). Steps and tolerance as above
    const Gap g = gradient_gap(across_edge(skew()), 1e-8, 1e-8, 0.5);
    INFO(show(g));
    CHECK(g.force < 1e-7);
    CHECK(g.moment < 1e-7);
}

TEST_CASE("a block lying across an acute edge of its base is pushed by −∇U", "[dem][contact]") {
    // B's +x side leans in by 0.1 m over its 0.5 m height (78.7° to its top): boundaries on planes
    // fixed to B that are not square to its top (that side's plane and the bisector with it) have
    // edge forces with a part along the normal. Steps and tolerance as above
    Corners c = box_corners(Vec3(1.0, 1.0, 0.5));
    for (int i : {1, 2}) c[size_t(i)].x() -= 0.1;   // bottom corners of the +x side
    for (auto& p : c) p += Vec3(0.0, 0.0, -0.25);
    const Gap g = gradient_gap(across_edge(skew(), &c), 1e-8, 1e-8, 0.5);
    INFO(show(g));
    CHECK(g.force < 1e-7);
    CHECK(g.moment < 1e-7);
}

TEST_CASE("a corner pressed into a wide base is pushed by −∇U", "[dem][contact]") {
    // a 0.4 m cube turned 0.3 rad about y and 0.05 about x, its lowest corner 3 mm into a wide
    // base: wedges under three faces, each tilted to the base, whose region ends only where
    // d = 0 or on an edge shared with another face in contact. Each face's couple ½kn·n × ∫d²∇d dA
    // is ½kn·n × ∮(d³/3)·m ds, and the three cancel along their shared edges: the force along the
    // normal at the pressure centres was already −∇U (pinned). Steps and tolerance as above
    Scene s = frictionless_scene();
    const Quat q = Quat(Eigen::AngleAxisd(0.05, Vec3::UnitX())) * Quat(Eigen::AngleAxisd(0.3, Vec3::UnitY()));
    double lowest = 0.0;
    for (int i = 0; i < 8; ++i)
        lowest = std::min(lowest, (q * Vec3(i & 1 ? 0.2 : -0.2, i & 2 ? 0.2 : -0.2, i & 4 ? 0.2 : -0.2)).z());
    add_box(s, "A", Vec3(0.4, 0.4, 0.4), Vec3(0.0, 0.0, -lowest - 0.003), false, q);
    add_box(s, "B", Vec3(2.0, 2.0, 0.5), Vec3(0.0, 0.0, -0.25), true);
    const Gap g = gradient_gap(s, 1e-8, 1e-8, 0.2);
    INFO(show(g));
    CHECK(g.force < 1e-7);
    CHECK(g.moment < 1e-7);
}

