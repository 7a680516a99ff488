// an element turned inside out (det F <= 0 at a Gauss point) is found by the batched kernel and
// stops the run, naming the block, the element and the time
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "backends/dem/dem_test_util.hpp"
#include "dem/deformable/deformable_body.hpp"
#include "dem/mesh.hpp"
#include "dem/world.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;
using namespace cairn::dem;
using Catch::Matchers::Contains;

namespace {
// internal forces of `body` at positions x; the inversion check runs inside
void forces(DeformableBody& body, const std::vector<Vec3>& x) {
    std::vector<Vec3> v(x.size(), Vec3::Zero()), f(x.size(), Vec3::Zero());
    body.add_internal_forces(x, v, f);
}
}  // namespace

TEST_CASE("det F <= 0 is found in the element that inverted, on both kernel paths", "[dem][deformable][inversion]") {
    const Material stone = test::stone();
    // a box (parallelepiped elements) and a tapered block (general elements, Jacobian per Gauss point)
    Corners tapered = box_corners(Vec3(2, 1, 1));
    for (int a = 4; a < 8; ++a) tapered[a].y() *= 0.5;
    const Corners shapes[2] = {box_corners(Vec3(2, 1, 1)), tapered};
    for (int k = 0; k < 2; ++k) {
        const Corners& shape = shapes[k];
        Mesh mesh = make_mesh(shape, {2, 1, 1});
        DeformableBody body(mesh, stone, MassScheme::lumped, 0.0, std::vector<char>(mesh.nodes.size(), 0));
        std::vector<Vec3> x = mesh.nodes;
        forces(body, x);
        CHECK(body.inverted_element() == -1);
        // the top nodes at x = 1 (i = 2, k = 1) moved from z = 0.5 to −1.5: the second element's
        // height varies linearly from 1 m at ξ = −1 to −1 m at ξ = +1, so det F = ∂z/∂Z = −ξ, and
        // the Gauss points at ξ = +1/√3 have det F = −1/√3; the first element is untouched
        for (int j = 0; j <= 1; ++j) x[size_t(mesh.node(2, j, 1))].z() = -1.5;
        forces(body, x);
        CHECK(body.inverted_element() == 1);
        CHECK(body.inverted_det() < 0.0);
        if (k == 0) CHECK(body.inverted_det() == Approx(-1.0 / std::sqrt(3.0)).epsilon(1e-12));
    }
}

TEST_CASE("a deformable block with young = 1e-300 stops the run as it turns inside out", "[dem][deformable][inversion]") {
    Scene s = test::stone_scene();
    s.materials[0].young = 1e-300;
    add_box(s, "ground", Vec3(3, 3, 1), Vec3(0, 0, -0.5), true);
    const int a = add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    s.blocks[size_t(a)].model = BlockModel::deformable;
    s.blocks[size_t(a)].mesh.divisions = {2, 2, 2};
    auto backend = test::build_dem(s);
    double t_fail = -1.0;
    const bool ok = test::run_dem(*backend, 1.0, [&](const Sample& x) { t_fail = x.t; });
    REQUIRE_FALSE(ok);
    CHECK_THAT(backend->failure(), Contains("block A: element ") && Contains("of its 2x2x2 mesh) turned inside out at t = ") &&
                                       Contains("young = 1e-300 Pa"));
    // with no stiffness the middle layer of nodes falls freely onto the bottom layer, which the
    // ground holds up (its spring deflection is below 2 mm): inversion comes before
    // sqrt(2·(0.5 m + 2 mm)/g)
    CHECK(t_fail > 0.0);
    CHECK(t_fail <= std::sqrt(2.0 * 0.502 / 9.81));

    // the same block in stone stands
    s.materials[0].young = 30e9;
    auto stone = test::build_dem(s);
    CHECK(test::run_dem(*stone, 0.05, [](const Sample&) {}));
}
