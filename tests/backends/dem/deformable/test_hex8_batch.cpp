// The batched (SIMD) hex8 kernel against the scalar reference hex8_internal_force: same forces,
// strain energy and damping power on distorted and on box meshes, whatever the thread count.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "dem/deformable/deformable_body.hpp"
#include "dem/deformable/hex8.hpp"
#include "dem/deformable/hex8_batch.hpp"
#include "dem/mesh.hpp"
#include "run/core_pool.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;
using namespace cairn::dem;

namespace {

const Material kStone = test::stone();

// a distorted hexahedron: its trilinear subdivision has no parallelepiped element
Corners distorted() {
    Corners c = box_corners(Vec3(1.0, 0.8, 1.2));
    c[6] += Vec3(0.1, 0.05, 0.08);
    c[1] += Vec3(0.04, -0.03, 0.0);
    c[4] += Vec3(-0.05, 0.02, 0.03);
    return c;
}

struct Result {
    std::vector<Vec3> f;
    double energy = 0.0, power = 0.0;
};

// the scalar reference, element by element
Result scalar(const Mesh& mesh, const std::vector<Vec3>& x, const std::vector<Vec3>& v, double beta) {
    Result r;
    r.f.assign(x.size(), Vec3::Zero());
    const Lame lm = lame(kStone.young, kStone.poisson);
    for (const auto& e : mesh.elements) {
        Corners c;
        Mat83 xe, ve, fe = Mat83::Zero();
        for (int a = 0; a < 8; ++a) {
            c[a] = mesh.nodes[e[a]];
            xe.row(a) = x[e[a]].transpose();
            ve.row(a) = v[e[a]].transpose();
        }
        r.energy += hex8_internal_force(hex8_reference(c), lm, xe, fe, beta, &ve, &r.power);
        for (int a = 0; a < 8; ++a) r.f[e[a]] -= fe.row(a).transpose();
    }
    return r;
}

Result batched(DeformableBody& body, const std::vector<Vec3>& x, const std::vector<Vec3>& v) {
    Result r;
    r.f.assign(x.size(), Vec3::Zero());
    r.energy = body.add_internal_forces(x, v, r.f);
    r.power = body.damping_power();
    return r;
}

// a large rotation, a finite strain (~5 %) and random node perturbations and velocities
void deform(const Mesh& mesh, std::vector<Vec3>& x, std::vector<Vec3>& v, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Mat3 a;
    a << 1.04, 0.02, -0.01, 0.015, 0.97, 0.03, -0.02, 0.01, 1.05;
    const Mat3 rot = Eigen::AngleAxisd(1.1, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
    x.clear();
    v.clear();
    for (const auto& p : mesh.nodes) {
        x.push_back(rot * (a * p) + Vec3(0.3, -0.2, 2.0) + 0.01 * Vec3(u(rng), u(rng), u(rng)));
        v.push_back(Vec3(u(rng), u(rng), u(rng)));
    }
}

void compare(const Mesh& mesh, double beta, size_t expected_parallelepipeds) {
    std::vector<char> free_nodes(mesh.nodes.size(), 0);
    DeformableBody body(mesh, kStone, MassScheme::lumped, beta, free_nodes);
    Hex8Batch batch(mesh.nodes, mesh.elements);
    REQUIRE(batch.parallelepiped_count() == expected_parallelepipeds);
    std::vector<Vec3> x, v;
    deform(mesh, x, v, 7);
    const Result ref = scalar(mesh, x, v, beta);
    double scale = 0.0;
    for (const auto& f : ref.f) scale = std::max(scale, f.norm());
    REQUIRE(scale > 1e6);
    REQUIRE(ref.energy > 0.0);
    set_openmp_threads(1);
    const Result one = batched(body, x, v);
    // both are sums of ~3000 rounded products per element, in different orders: they agree to
    // a few hundred ulps of the largest force; energy and power likewise relative to their size
    for (size_t n = 0; n < x.size(); ++n) CHECK((one.f[n] - ref.f[n]).norm() < 1e-12 * scale);
    CHECK(one.energy == Approx(ref.energy).epsilon(1e-12));
    if (beta > 0.0) {
        REQUIRE(ref.power > 0.0);
        CHECK(one.power == Approx(ref.power).epsilon(1e-12));
    } else {
        CHECK(one.power == 0.0);
    }
    // deterministic: bit-identical on 2 threads (per-element store and fixed-order gather)
    set_openmp_threads(2);
    const Result two = batched(body, x, v);
    set_openmp_threads(1);
    for (size_t n = 0; n < x.size(); ++n) CHECK(two.f[n] == one.f[n]);
    CHECK(two.energy == one.energy);
    CHECK(two.power == one.power);
}

}  // namespace

TEST_CASE("batched hex8 forces, energy and damping power equal the scalar kernel on a distorted mesh",
          "[dem][hex8][batch]") {
    // 5x4x7 = 140 elements: 17 full batches and a partial one (padding lanes); general Jacobians
    Mesh mesh = make_mesh(distorted(), {5, 4, 7});
    compare(mesh, 0.0, 0);
    compare(mesh, 2e-4, 0);
}

TEST_CASE("batched hex8 forces equal the scalar kernel on a box mesh of parallelepipeds", "[dem][hex8][batch]") {
    // a sheared box: every element is the same parallelepiped (constant Jacobian path)
    Corners c = box_corners(Vec3(1.0, 0.6, 0.9));
    for (auto& p : c) p += Vec3(0.3 * p.z(), 0.0, 0.1 * p.x());
    Mesh mesh = make_mesh(c, {6, 3, 9});
    compare(mesh, 0.0, mesh.elements.size());
    compare(mesh, 1e-3, mesh.elements.size());
    Mesh single = make_mesh(c, {1, 1, 1});
    compare(single, 1e-3, 1);
}
