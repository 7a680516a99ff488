// ODE's error handler: an internal error stops the run with ODE's message instead of aborting
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>

#include "engine_scenes.hpp"
#include "registry.hpp"

using namespace cairn;
using namespace cairn::test;

TEST_CASE("ode: an internal error stops the run with its message and a rebuilt world runs", "[engines]") {
    const auto names = engine_names();
    if (std::find(names.begin(), names.end(), "ode") == names.end()) return;   // not built in
    Scene s = base_scene("fault");
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 10), false);
    // a scene file cannot hold this (the loader rejects it): a NaN spin makes ODE's quaternion
    // update fail its normalisation assertion inside dWorldStep
    s.blocks[0].angular_velocity = Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
    auto b = make_backend("ode");
    b->build(s, RunOptions{});
    CHECK(b->step() == StepStatus::unstable);
    CHECK_THAT(b->failure(), Catch::Contains("ODE internal error") && Catch::Contains("t = 0"));
    // the abandoned world is never stepped again, and the last state can still be read
    CHECK(b->step() == StepStatus::unstable);
    CHECK(b->sample().blocks.size() == 1);
    // a fresh build of the same backend object runs normally
    s.blocks[0].angular_velocity = Vec3::Zero();
    b->build(s, RunOptions{});
    for (int i = 0; i < 100; ++i) REQUIRE(b->step() == StepStatus::ok);
    CHECK(b->sample().blocks[0].position.z() < 10.0);
}
