// the spring-block rocking reference: its hitting rows, its energy balance, its convergence, and
// its rigid limit against Housner's closed-form first impact
#include <catch2/catch.hpp>

#include <cmath>

#include "analytic/oracles.hpp"
#include "analytic/spring_block.hpp"

using namespace cairn::oracle;

namespace {
// reading B of the paper's rocking case: 0.7 × 0.2 × 1.0 m, 364 kg, on kn = ks = 3e7 N/m³, μ = 0.8
SpringBlock reading_b(double kn, double zeta = 0.0) {
    return {0.7, 1.0, 0.7 * 0.2 * 1.0 * 2600.0, 9.81, kn, kn, 0.8, spring_rows(0.7, 0.2, 1, 0.1), zeta};
}
double rocking_energy(const SpringBlock& b, double theta0) {
    HousnerBlock hb{0.5 * b.width, 0.5 * b.height, b.g};
    return b.mass * b.g * hb.radius() * (std::cos(hb.alpha() - theta0) - std::cos(hb.alpha()));
}
}  // namespace

TEST_CASE("spring rows: the hitting grid of a face, and of a face meshed in two", "[oracle][spring_block]") {
    // one 0.7 m face at 0.1 m: 8 rows 0.1 m apart, trapezoid weights
    auto r = spring_rows(0.7, 0.2, 1, 0.1);
    REQUIRE(r.size() == 8);
    CHECK(r.front().x == Approx(-0.35));
    CHECK(r.back().x == Approx(0.35));
    CHECK(r.front().area == Approx(0.5 * 0.1 * 0.2));
    CHECK(r[3].area == Approx(0.1 * 0.2));
    // two 0.35 m faces: 5 points each at 0.0875 m, the shared middle row carries both halves
    auto d = spring_rows(0.7, 0.2, 2, 0.1);
    REQUIRE(d.size() == 9);
    CHECK(d[4].x == Approx(0.0).margin(1e-15));
    CHECK(d[4].area == Approx(0.0875 * 0.2));
    double sum = 0.0;
    for (const auto& x : d) sum += x.area;
    CHECK(sum == Approx(0.7 * 0.2).epsilon(1e-14));
}

TEST_CASE("spring block: without friction losses or dashpots its energy closes", "[oracle][spring_block]") {
    // no shear springs: no slip; the only error is the integrator's at the contact switches
    SpringBlock b = reading_b(3e7);
    b.ks = 0.0;
    const double th0 = M_PI / 6;
    const auto tr = b.rock(th0, 3.0, 1e-3);
    REQUIRE(tr.impacts.size() >= 2);
    // 1e-3 of the rocking energy: velocity Verlet at T/1000 with a contact switch per row and impact
    CHECK(tr.energy_error < 1e-3 * rocking_energy(b, th0));
}

TEST_CASE("spring block: converged in its step, and damping only takes energy away", "[oracle][spring_block]") {
    const double th0 = M_PI / 6;
    SpringBlock fine = reading_b(3e7);
    fine.steps_per_period = 4000.0;
    const auto a = reading_b(3e7).rock(th0, 3.0, 1e-3), b = fine.rock(th0, 3.0, 1e-3);
    REQUIRE(a.amplitudes.size() >= 2);
    REQUIRE(b.amplitudes.size() >= 2);
    // the amplitudes the validation judges at 2 % move by < 1e-3 when the step is 4× smaller
    for (size_t k = 0; k < 2; ++k) CHECK(a.amplitudes[k] == Approx(b.amplitudes[k]).epsilon(1e-3));
    // the undamped block loses some energy at an impact (slip, the block's bounce on the springs),
    // and the dashpots add to it: ζ = 0.2 rocks lower
    CHECK(a.amplitudes[0] < th0);
    const auto d = reading_b(3e7, 0.2).rock(th0, 3.0, 1e-3);
    REQUIRE_FALSE(d.amplitudes.empty());
    CHECK(d.amplitudes[0] < a.amplitudes[0]);
}

TEST_CASE("spring block: stiff springs give Housner's first impact", "[oracle][spring_block]") {
    HousnerBlock hb{0.35, 0.5, 9.81};
    const double th0 = M_PI / 6;
    // before the first impact the block turns about its edge; at kn = 3e11 the edge sinks 2e-5 m:
    // the time moves by < 1e-4 of t1 (the sinking edge delays it: 0.13 % at 3e7)
    const auto tr = reading_b(3e11).rock(th0, 0.8, 1e-3);
    REQUIRE_FALSE(tr.impacts.empty());
    CHECK(tr.impacts[0] == Approx(hb.first_impact(th0)).epsilon(1e-4));
    // and the paper's kn = 3e7 is 0.13 % late
    const auto soft = reading_b(3e7).rock(th0, 0.8, 1e-3);
    REQUIRE_FALSE(soft.impacts.empty());
    CHECK(soft.impacts[0] / hb.first_impact(th0) - 1.0 == Approx(0.0013).margin(5e-4));
}

TEST_CASE("spring block: a contact too stiff to integrate is refused, not run for ever", "[oracle][spring_block]") {
    // kn = 1e20 N/m³ would need ~1e12 steps over 3 s
    CHECK_THROWS_WITH(reading_b(1e20).rock(M_PI / 6, 3.0, 1e-3), Catch::Matchers::Contains("more than 1e8"));
}
