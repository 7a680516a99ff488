// The pushover accuracy measure's pieces: the settings tried, the cheapest point reaching the
// tolerance, the csv round trip.
#include <catch2/catch.hpp>

#include <cmath>

#include "bench/scale_pushover.hpp"

using namespace cairn;

TEST_CASE("pushover settings: cheapest first, ODE on its exact stepper", "[bench][scale]") {
    const auto dem = bench::pushover_settings("dem");
    REQUIRE(dem.size() == 3);
    CHECK(dem[0][1].key == "run.dt_safety");
    CHECK(dem[0][1].value == "0.4");   // the largest fraction of the critical step: the cheapest
    CHECK(dem[2][1].value == "0.1");
    const auto ode = bench::pushover_settings("ode");
    REQUIRE(ode.size() == 3);
    CHECK(ode[0][0].value == "1e-3");
    CHECK(ode[0][1].key == "backends.ode.stepper");
    CHECK(bench::pushover_settings("bullet")[2].size() == 1);
}

TEST_CASE("pushover points: the cheapest completed one within the tolerance", "[bench][scale]") {
    std::vector<bench::PushoverPoint> pts{
        {"bullet", "run.dt=1e-3", 1e-3, 0.262, 0.2533, 0.262 / 0.2533 - 1, 1.0, "completed"},   // +3.4 %: out
        {"bullet", "run.dt=3e-4", 3e-4, 0.255, 0.2533, 0.255 / 0.2533 - 1, 3.0, "completed"},   // +0.7 %
        {"bullet", "run.dt=1e-4", 1e-4, 0.254, 0.2533, 0.254 / 0.2533 - 1, 9.0, "completed"},
        {"dem", "run.dt_safety=0.4", 1e-4, NAN, 0.2533, NAN, 5.0, "completed"},                 // never turned
        {"dem", "run.dt_safety=0.2", 5e-5, 0.2535, 0.2533, 0.2535 / 0.2533 - 1, 1.0, "unstable: x"}};
    const auto* b = bench::cheapest_reaching(pts, "bullet", 0.02);
    REQUIRE(b);
    CHECK(b->dt == 3e-4);
    CHECK(bench::cheapest_reaching(pts, "dem", 0.02) == nullptr);   // NaN and unstable do not count
    const auto back = bench::parse_pushover_csv(bench::pushover_csv(pts));
    REQUIRE(back.size() == pts.size());
    CHECK(back[1].setting == "run.dt=3e-4");
    CHECK(back[1].error == Approx(pts[1].error));
    CHECK(std::isnan(back[3].multiplier));
    CHECK(back[4].status == "unstable: x");
}
