// The large model's pieces: the tower of about n bricks and the csv round trip.
#include <catch2/catch.hpp>

#include "bench/scale_large.hpp"

using namespace cairn;

TEST_CASE("large tower: about the asked number of bricks in about √n courses", "[bench][scale]") {
    // a course of a length × width tower holds 2·length + 2·width − 2 bricks
    for (int n : {100, 1000, 3000, 10000}) {
        const TowerSpec t = bench::large_tower(n);
        INFO(n);
        CHECK(t.length >= 3);
        CHECK(t.width >= 3);
        CHECK(tower_brick_count(t) == (long long)t.courses * (2 * t.length + 2 * t.width - 2));
        // the sides are whole brick lengths: a course is within 4 bricks of n / courses
        CHECK(std::abs(double(tower_brick_count(t)) - n) <= 4.0 * t.courses);
    }
    CHECK(tower_brick_count(bench::large_tower(100)) == 100);      // 10 courses of 3 × 3
    CHECK(tower_brick_count(bench::large_tower(10000)) == 10000);  // 100 courses of 25 × 26
}

TEST_CASE("large run csv: a row survives the round trip", "[bench][scale]") {
    bench::LargeRun r;
    r.blocks = 10000, r.duration = 0.2, r.dt = 3.7e-5, r.critical_step = 3.7e-4, r.steps = 5400;
    r.wall_seconds = 1200, r.build_seconds = 2, r.peak_mb = 160, r.contacts = 21000, r.max_balance_error = 2e-6;
    r.energy_closed = true, r.status = "completed";
    const auto back = bench::parse_large_csv(bench::large_csv(r));
    CHECK(back.blocks == r.blocks);
    CHECK(back.steps == r.steps);
    CHECK(back.dt == Approx(r.dt));
    CHECK(back.cost() == Approx(6000.0));   // 1200 s for 0.2 s
    CHECK(back.ns_per_contact() == Approx(1e9 * 1200 / (5400 * 21000.0)));
    CHECK(back.energy_closed);
    CHECK(back.status == "completed");
}
