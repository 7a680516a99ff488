// which variants compare runs for a user scene, and the note on one that will run far longer
#include <catch2/catch.hpp>

#include "scene_compare/variants.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

/// `bricks` free 0.4 m cubes in a row on a slab, run for `duration` s at dt = 1e-4 s
Scene row(int bricks, double duration) {
    Scene s = test::stone_scene(0.6);
    s.run.dt = 1e-4;
    s.run.duration = duration;
    for (int i = 0; i < bricks; ++i) test::add_box(s, "b" + std::to_string(i), Vec3(0.4, 0.4, 0.4), Vec3(0.4 * i, 0, 0.2), false);
    test::add_box(s, "G", Vec3(0.4 * bricks + 1, 2, 0.4), Vec3(0.2 * bricks, 0, -0.2), true);
    return s;
}

std::vector<validation::Variant> variants(const std::vector<std::string>& backends) {
    std::vector<validation::Variant> v;
    for (const auto& b : backends) v.push_back({b + "-rigid", b, "rigid", "rigid"});
    return v;
}

}  // namespace

TEST_CASE("compare variants: a long siconos run is announced with its estimate", "[compare][variants]") {
    // 34 free blocks over 4 s at 1e-4 s: 40 000 steps of 71 ms, 47 min
    const std::string note = scene_compare::long_run_note(row(34, 4.0), variants({"dem", "bullet", "siconos"}));
    CHECK_THAT(note, Catch::Contains("34 free blocks over 40000 steps need about 47 min"));
    CHECK_THAT(note, Catch::Contains("--backends dem,bullet leaves it out"));
    // twice the blocks: four times the step, 3 h
    CHECK_THAT(scene_compare::long_run_note(row(68, 4.0), variants({"siconos"})), Catch::Contains("about 3 h"));
    // nothing under ten minutes, and nothing without siconos
    CHECK(scene_compare::long_run_note(row(5, 2.0), variants({"dem", "siconos"})).empty());
    CHECK(scene_compare::long_run_note(row(34, 4.0), variants({"dem", "bullet", "ode", "mujoco"})).empty());
}
