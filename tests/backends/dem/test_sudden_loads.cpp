// which loads the contact springs cannot follow: a step after t = 0, a record's edge faster than
// the springs' period; the loads acting at t = 0 (settled), slow ramps and small steps are not
#include <catch2/catch.hpp>

#include <memory>

#include "dem/sudden_loads.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

constexpr double kPeriod = 4e-3;   // s: a 0.4 m cube on kn = 1e9 rings at about this

/// a 0.4 m stone cube A (weight 1632.4 N) on a fixed base B
Scene cube() {
    Scene s = test::stone_scene();
    test::add_box(s, "B", Vec3(3.0, 2.0, 0.5), Vec3(0, 0, -0.25), true);
    test::add_box(s, "A", Vec3(0.4, 0.4, 0.4), Vec3(0, 0, 0.2), false);
    return s;
}

/// a force of `newtons` along x on A (block 1) from `start`, over `ramp`
LoadDef push(double newtons, double start, double ramp) {
    LoadDef l;
    l.block = 1;
    l.force = Vec3(newtons, 0, 0);
    l.start = start;
    l.ramp = ramp;
    return l;
}

/// a history of (time, value) pairs
std::shared_ptr<const TimeSeries> history(std::vector<double> t, std::vector<double> v) {
    return std::make_shared<const TimeSeries>(TimeSeries{std::move(t), std::move(v)});
}

}  // namespace

TEST_CASE("sudden loads: a step after t = 0 is one, a slow ramp or a load from t = 0 is not", "[dem][sudden]") {
    Scene s = cube();
    s.loads.push_back(push(734.6, 0.5, 0.0));
    auto first = dem::first_sudden_load(s, kPeriod);
    REQUIRE(first);
    CHECK(first->time == 0.5);
    CHECK(first->load == 0);
    s.loads[0].ramp = 0.2;   // 50 periods: the springs follow
    CHECK_FALSE(dem::first_sudden_load(s, kPeriod));
    s.loads[0] = push(734.6, 0.0, 0.0);   // at t = 0: the settling takes it in
    CHECK_FALSE(dem::first_sudden_load(s, kPeriod));
    s.loads[0] = push(50.0, 0.5, 0.0);   // 3 % of the weight: below the 5 % counted
    CHECK_FALSE(dem::first_sudden_load(s, kPeriod));
    // a step on the fixed base is none of the springs' business
    LoadDef on_base = push(1e4, 0.3, 0.0);
    on_base.block = 0;
    s.loads.push_back(on_base);
    CHECK_FALSE(dem::first_sudden_load(s, kPeriod));
    // the earliest of two
    s.loads.push_back(push(734.6, 0.8, 0.0));
    s.loads.push_back(push(734.6, 0.6, 0.0));
    first = dem::first_sudden_load(s, kPeriod);
    REQUIRE(first);
    CHECK(first->time == 0.6);
    CHECK(first->load == 3);
}

TEST_CASE("sudden loads: a record's edges count when faster than the period", "[dem][sudden]") {
    Scene s = cube();
    // a ground pulse of 0.45 g as the loader writes it: −m·a_g, the history in m/s²
    LoadDef pulse = push(-166.4, 0.0, 0.0);
    pulse.body = true;
    pulse.history = history({0, 0.2, 0.201, 0.7, 0.701, 2.0}, {0, 0, 4.41, 4.41, 0, 0});
    s.loads.push_back(pulse);
    auto first = dem::first_sudden_load(s, kPeriod);
    REQUIRE(first);
    CHECK(first->time == Approx(0.2));
    // 0.1 s edges: 25 periods, followed
    s.loads[0].history = history({0, 0.2, 0.3, 0.7, 0.8, 2.0}, {0, 0, 4.41, 4.41, 0, 0});
    CHECK_FALSE(dem::first_sudden_load(s, kPeriod));
    // a record that starts at 1 s at 0.3 g, from the zero before its span; and one that stops
    // at 1.5 s while still at 0.3 g
    s.loads[0].history = history({1.0, 2.0}, {2.94, 2.94});
    first = dem::first_sudden_load(s, kPeriod);
    REQUIRE(first);
    CHECK(first->time == Approx(1.0));
    s.loads[0].history = history({0.0, 1.5}, {0.0, 2.94});
    first = dem::first_sudden_load(s, kPeriod);
    REQUIRE(first);
    CHECK(first->time == Approx(1.5));
    // the same, shifted by the ground motion's start
    s.loads[0].start = 0.25;
    first = dem::first_sudden_load(s, kPeriod);
    REQUIRE(first);
    CHECK(first->time == Approx(1.75));
}
