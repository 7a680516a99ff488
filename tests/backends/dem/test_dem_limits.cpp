// the dem model's memory and hitting points are estimated before anything is built: absurd
// meshes and grid spacings are refused naming file, key and value
#include <catch2/catch.hpp>

#include "backends/dem/dem_test_util.hpp"
#include "dem/block_builder.hpp"
#include "error.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;
using namespace cairn::dem;
using Catch::Matchers::Contains;

namespace {
Scene cube_on_ground() {
    Scene s = test::stone_scene();
    s.source = "t.toml";
    add_box(s, "ground", Vec3(3, 3, 1), Vec3(0, 0, -0.5), true);
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    return s;
}

std::string error_of(const Scene& s, const RunLimits& limits = {}) {
    try {
        check_build_size(s, limits);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

RunLimits budget(double bytes) {
    RunLimits l;
    l.memory_budget = bytes;
    return l;
}
}  // namespace

TEST_CASE("mesh.divisions = [1000, 1000, 1000] is refused before any allocation", "[dem][limits]") {
    Scene s = cube_on_ground();
    s.blocks[1].model = BlockModel::deformable;
    s.blocks[1].mesh.divisions = {1000, 1000, 1000};
    CHECK_THAT(error_of(s), Contains("t.toml: blocks.A.mesh.divisions = [1000, 1000, 1000]: 1e+09 elements") &&
                                Contains("beyond the engine's 32-bit indices"));
    // through the backend's build, with the default budget
    CHECK_THROWS_WITH(test::build_dem(s), Contains("blocks.A.mesh.divisions = [1000, 1000, 1000]"));
    // 1e6 elements fit the indices but not a 1 GiB budget
    s.blocks[1].mesh.divisions = {100, 100, 100};
    CHECK_THAT(error_of(s, budget(1 << 30)),
               Contains("t.toml: blocks.A.mesh.divisions = [100, 100, 100]: the model would take about ") &&
                   Contains("beyond the memory budget of 1 GiB"));
    CHECK(error_of(s, budget(64.0 * (1 << 30))).empty());
}

TEST_CASE("a tiny contact.grid_spacing is refused before any allocation", "[dem][limits]") {
    Scene s = cube_on_ground();
    // 1e-12: (3 m / 1e-12 + 1)² = 9e24 points on the ground's top face (once 4 after an int overflow)
    s.contact.grid_spacing = 1e-12;
    CHECK_THAT(error_of(s), Contains("t.toml: contact.grid_spacing = 1e-12: 9e+24 hitting points on one face"));
    s.contact.grid_spacing = 1e-5;   // 1e10 on the ground's faces (once std::bad_alloc)
    CHECK_THAT(error_of(s), Contains("contact.grid_spacing = 1e-05: 9e+10 hitting points on one face"));
    // 1e-3: the ground 2·3001² + 4·3001·1001, the cube 6·1001²: 3.6e7 points, beyond 1e6
    s.contact.grid_spacing = 1e-3;
    CHECK_THAT(error_of(s), Contains("contact.grid_spacing = 0.001: 3.6e+07 hitting points on the block faces, "
                                     "beyond the limit of 1e+06 (--allow-large lifts it"));
    RunLimits large = budget(1 << 30);
    large.allow_large = true;
    CHECK_THAT(error_of(s, large), Contains("contact.grid_spacing = 0.001: the model would take about") &&
                                       Contains("beyond the memory budget of 1 GiB"));
}

TEST_CASE("the estimate counts the mesh exactly and bounds the hitting points built", "[dem][limits]") {
    Scene s = cube_on_ground();
    s.contact.scheme = ContactScheme::paper;   // hitting points on the paper's grid
    s.blocks[1].model = BlockModel::deformable;
    s.blocks[1].mesh.divisions = {2, 3, 4};
    const BuildEstimate est = estimate_build(s);
    // the ground is one element (8 nodes); A has 2·3·4 elements and 3·4·5 nodes
    CHECK(est.elements == 1 + 24);
    CHECK(est.nodes == 8 + 60);
    size_t hits = 0;
    for (const auto& def : s.blocks)
        for (const auto& face : make_block(def, s).hits) hits += face.size();
    // the estimate counts every face's grid before shared edge points are merged: an upper bound
    CHECK(est.hit_points >= double(hits));
    CHECK(est.hit_points <= 2.0 * double(hits));
    CHECK(error_of(s).empty());
}
