// The scale bench's pieces: the closed-form settlement, the wall shapes, the exponent fit and
// the csv round trips.
#include <catch2/catch.hpp>

#include <cmath>

#include "bench/scale_bench.hpp"

using namespace cairn;

TEST_CASE("wall settlement: the sum of the joints' compressions", "[bench][scale]") {
    // one course: one joint under ρ g h; two courses: 2ρgh + ρgh, closed by kn
    const double rho = 2600, g = 9.81, h = 0.2, kn = 3e9, p = rho * g * h / kn;
    CHECK(bench::wall_settlement(1, rho, g, h, kn) == Approx(p).epsilon(1e-14));
    CHECK(bench::wall_settlement(2, rho, g, h, kn) == Approx(3 * p).epsilon(1e-14));
    double sum = 0.0;
    for (int c = 0; c < 30; ++c) sum += (30 - c) * p;
    CHECK(bench::wall_settlement(30, rho, g, h, kn) == Approx(sum).epsilon(1e-12));
}

TEST_CASE("scale walls: about the asked number of bricks, nearly square", "[bench][scale]") {
    for (int n : {100, 1000, 3000, 10000}) {
        const auto s = bench::scale_wall_shape(n);
        const int got = s[0] * s[1];
        CHECK(got >= n);
        CHECK(got < n + s[1]);   // at most one course more than needed
        // 0.4 m long and 0.2 m tall bricks: twice as many courses as bricks per course, a square
        const double aspect = (0.4 * s[1]) / (0.2 * s[0]);
        CHECK(aspect > 0.9);
        CHECK(aspect < 1.3);   // the ceiling of √(n/2) on a small wall (100 bricks: 8 × 13)
    }
}

TEST_CASE("fitted exponent: the slope of an exact power law, NaN below two points", "[bench][scale]") {
    std::vector<double> n{1000, 3000, 10000}, y;
    for (double v : n) y.push_back(2.5e-3 * std::pow(v, 1.3));
    CHECK(bench::fitted_exponent(n, y) == Approx(1.3).epsilon(1e-10));
    CHECK(std::isnan(bench::fitted_exponent({1000}, {1.0})));
    // non-positive values are left out
    CHECK(bench::fitted_exponent({1000, 3000, 10000, 5}, {1.0, 3.0, 10.0, 0.0}) == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("scale csv files read back what was written", "[bench][scale]") {
    std::vector<bench::ScaleRow> rows{{"dem", 1008, 3e-4, 5, 0.0123, 41.0, 88.5, "completed"},
                                      {"ode", 10011, 1e-3, 5, 0.5, 500.0, 900.0, "unstable: a, b"}};
    const auto back = bench::parse_scale_csv(bench::scale_csv(rows));
    REQUIRE(back.size() == 2);
    CHECK(back[1].backend == "ode");
    CHECK(back[1].blocks == 10011);
    CHECK(back[1].status == "unstable: a, b");
    CHECK(back[0].cost == Approx(41.0));
    std::vector<bench::ScaleAccuracy> acc{{"bullet", 1e-3, 9.3e-5, 9.35e-5, -0.005, "completed"}};
    const auto acc_back = bench::parse_scale_accuracy_csv(bench::scale_accuracy_csv(acc));
    REQUIRE(acc_back.size() == 1);
    CHECK(acc_back[0].error == Approx(-0.005));
    CHECK(bench::reaching_dt(acc_back, "bullet", 0.01) == 1e-3);
    CHECK(bench::reaching_dt(acc_back, "bullet", 0.001) == 0.0);
}
