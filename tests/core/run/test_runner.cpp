// run_scene(): sampling, step count, and stopping runs that go unstable, with a fake backend
#include <catch2/catch.hpp>

#include <cmath>

#include "error.hpp"
#include "fake_backend.hpp"
#include "run/runner.hpp"

using namespace cairn;
using namespace cairn::testing;
using Catch::Matchers::Contains;

TEST_CASE("run_scene samples at t = 0, every output interval and the last step", "[runner]") {
    Scene scene = ballistic_scene();
    FakeBackend backend;

    SECTION("duration a whole number of output intervals") {
        // 0.1 / 1e-3 is 100.00000000000001 in floating point: still 100 steps
        const RunResult r = run_scene(backend, scene, {});
        CHECK(r.status == RunStatus::completed);
        CHECK(r.message.empty());
        CHECK(r.steps == 100);
        CHECK(r.output_every == 10);
        REQUIRE(r.samples.size() == 11);
        for (size_t i = 0; i < r.samples.size(); ++i)
            CHECK(r.samples[i].t == Approx(0.01 * double(i)).margin(1e-15));
        CHECK(r.dt == 1e-3);
        CHECK(r.critical_step == 2e-3);
        CHECK(r.wall_seconds >= 0.0);
    }
    SECTION("a last step that is not on the output grid is recorded too") {
        scene.run.duration = 0.105;
        const RunResult r = run_scene(backend, scene, {});
        CHECK(r.steps == 105);
        REQUIRE(r.samples.size() == 12);
        CHECK(r.samples[10].t == Approx(0.1));
        CHECK(r.samples.back().t == Approx(0.105));
    }
    SECTION("an output interval below dt samples every step") {
        scene.run.output_interval = 1e-5;
        const RunResult r = run_scene(backend, scene, {});
        CHECK(r.output_every == 1);
        CHECK(r.samples.size() == 101);
    }
    SECTION("the output interval is rounded to whole steps") {
        scene.run.output_interval = 0.0104;   // 10.4 steps -> 10
        CHECK(run_scene(backend, scene, {}).output_every == 10);
    }
}

TEST_CASE("run_scene passes the run options to build and propagates its errors", "[runner]") {
    Scene scene = ballistic_scene();
    FakeBackend backend;
    RunOptions options;
    options.contact_mode = "matched";
    run_scene(backend, scene, options);
    CHECK(backend.options().contact_mode == "matched");

    scene.blocks.clear();
    CHECK_THROWS_WITH(run_scene(backend, scene, {}), Contains("no block"));
}

TEST_CASE("an exact backend closes the energy balance without a drift flag", "[runner]") {
    Scene scene = ballistic_scene();
    FakeBackend backend;
    const RunResult r = run_scene(backend, scene, {});
    CHECK_FALSE(r.energy_drift);
    // analytic energies: the balance closes to rounding of ~10 J sums (1e-15 relative)
    CHECK(r.max_balance_error < 1e-12);
}

TEST_CASE("a NaN in a sample stops the run at that sample", "[runner]") {
    Scene scene = ballistic_scene();
    FakeBackend backend(Faults{37});
    const RunResult r = run_scene(backend, scene, {});
    CHECK(r.status == RunStatus::unstable);
    // the NaN appears at step 37 and is seen at the next sample, step 40
    CHECK(r.steps == 40);
    CHECK_THAT(r.message, Contains("unstable at t = 0.04 s"));
    CHECK_THAT(r.message, Contains("not finite"));
    CHECK_THAT(r.message, Contains("time step 1.00e-03 s, critical step 2.00e-03 s"));
    CHECK_THAT(r.message, Contains("dt = \"auto\""));
    // the partial trajectory keeps only finite samples
    REQUIRE(r.samples.size() == 4);
    CHECK(r.samples.back().t == Approx(0.03));
}

TEST_CASE("a step the backend reports unstable stops the run with its reason", "[runner]") {
    Scene scene = ballistic_scene();
    Faults f;
    f.unstable_at_step = 25;
    FakeBackend backend(f);
    const RunResult r = run_scene(backend, scene, {});
    CHECK(r.status == RunStatus::unstable);
    CHECK(r.steps == 25);
    CHECK_THAT(r.message,
               Contains("unstable at t = 0.025 s: contact spring overshoot; time step 1.00e-03 s, "
                        "critical step 2.00e-03 s"));
    // samples at 0, 0.01, 0.02, then the (finite) state at failure
    REQUIRE(r.samples.size() == 4);
    CHECK(r.samples.back().t == Approx(0.025));
}

TEST_CASE("energy growing without a source stops the run", "[runner]") {
    Scene scene = ballistic_scene();
    scene.run.duration = 0.5;
    Faults f;
    f.growth_rate = 0.1;   // x e per output interval: passes any scale within ~0.15 s
    FakeBackend backend(f);
    const RunResult r = run_scene(backend, scene, {});
    CHECK(r.status == RunStatus::unstable);
    CHECK(r.steps < 200);
    CHECK_THAT(r.message, Contains("energy growing without a source"));
    CHECK_THAT(r.message, Contains("critical step 2.00e-03 s"));
    CHECK(r.energy_drift);
    CHECK(r.max_balance_error > 1.0);
    // the sample that showed the growth is kept: its balance error exceeds the 1 J floor of the scale
    REQUIRE(r.samples.size() >= 2);
    CHECK(r.samples.back().energy.total() - r.samples.front().energy.total() > 1.0);
}

TEST_CASE("slow drift is flagged but the run completes", "[runner]") {
    Scene scene = ballistic_scene();
    Faults f;
    f.drift_per_second = 2.0;   // 0.2 J by t = 0.1 s, against a scale of ~8-10 J: 2-3 %
    FakeBackend backend(f);
    const RunResult r = run_scene(backend, scene, {});
    CHECK(r.status == RunStatus::completed);
    INFO("max balance error " << r.max_balance_error);
    CHECK(r.energy_drift);
    CHECK(r.max_balance_error > 0.01);
    CHECK(r.max_balance_error < 0.05);
}

TEST_CASE("energy appearing after losses the backend does not book is named with its time", "[runner]") {
    Scene scene = ballistic_scene();
    Faults f;
    f.drift_per_second = -2.0;   // unbooked losses: the balance error falls to -0.1 J by t = 0.05 s
    f.jump_at_step = 50;         // then 3 J appear at t = 0.05 s: a rise of 3 J from that lowest value
    f.jump_energy = 3.0;
    FakeBackend backend(f);
    const RunResult r = run_scene(backend, scene, {});
    CHECK(r.status == RunStatus::completed);
    // the bar's scale is the flight's motion energy, ~7-9 J (5 J kinetic at start, ~2 J of
    // potential exchanged; the 2 kg, 0.17 m cube's m·g·diameter is 3.4 J): 3 J is over a third of it
    CHECK(r.energy_created);
    // the rise from the lowest error (-0.1 J at 0.04 s) to 0.05 s: 3 J + 0.02 J of losses in between undone
    CHECK(r.energy_gain == Approx(3.0 - 2.0 * 0.01).margin(1e-9));
    CHECK(r.energy_gain_time == Approx(0.05));
    CHECK_THAT(energy_created_text(r), Contains("energy appeared from nowhere") && Contains("t = 0.05 s"));
}

TEST_CASE("unbooked losses and a slow drift are no energy created", "[runner]") {
    Scene scene = ballistic_scene();
    Faults f;
    SECTION("losses only: the balance error only falls") {
        f.drift_per_second = -20.0;
        FakeBackend backend(f);
        const RunResult r = run_scene(backend, scene, {});
        CHECK_FALSE(r.energy_created);
        CHECK(r.energy_gain < 1e-12);
        CHECK(energy_created_text(r).empty());
    }
    SECTION("a gain of 2-3 % of the motion's energy is drift, below the 10 % bar") {
        f.drift_per_second = 2.0;
        FakeBackend backend(f);
        const RunResult r = run_scene(backend, scene, {});
        CHECK(r.energy_drift);
        CHECK_FALSE(r.energy_created);
        CHECK(r.energy_gain == Approx(0.2).margin(1e-9));
    }
}
