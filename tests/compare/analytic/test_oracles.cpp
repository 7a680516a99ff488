// the analytic oracles against the numbers of docs/physics.md
#include <catch2/catch.hpp>

#include <cmath>

#include "analytic/oracles.hpp"

using namespace cairn::oracle;

namespace {
constexpr double kMass = 2600.0, kStiff = 3e7, kG = 9.81;
constexpr double kDeg = M_PI / 180.0;
}  // namespace

TEST_CASE("stability and impact closed forms match docs/physics.md", "[oracle]") {
    RestingBlock rest{kMass, kStiff, kG};
    // docs/physics.md prints 4-5 significant digits: compare to half a unit of the last digit
    CHECK(rest.penetration() == Approx(8.502e-4).margin(0.5e-7));
    CHECK(rest.period() == Approx(0.058493).margin(0.5e-6));
    DroppedBlock drop{kMass, kStiff, kG, 0.1};
    CHECK(drop.impact_speed() == Approx(1.400714).margin(0.5e-6));
    CHECK(drop.first_contact() == Approx(0.142784).margin(0.5e-6));
    CHECK(drop.contact_time() == Approx(0.030459).margin(0.5e-6));
    CHECK(drop.max_penetration() == Approx(13.918e-3).margin(0.5e-6));
    CHECK(drop.bounce_period() == Approx(0.316027).margin(0.5e-6));
}

TEST_CASE("the damped drop without damping reproduces the closed forms", "[oracle]") {
    DampedDrop d{kMass, kStiff, 0.0, kG, 0.1};
    DroppedBlock closed{kMass, kStiff, kG, 0.1};
    auto b = d.first_bounce();
    // RK4 at T/2e5 steps, crossing interpolated linearly: errors far below 1e-6 relative
    CHECK(b.contact_time == Approx(closed.contact_time()).epsilon(1e-6));
    CHECK(b.max_penetration == Approx(closed.max_penetration()).epsilon(1e-6));
    CHECK(b.restitution == Approx(1.0).epsilon(1e-6));
    CHECK(d.bounce_period() == Approx(closed.bounce_period()).epsilon(1e-6));
    // free fall before contact, and back at the 0.10 m gap at the apex one bounce period later
    auto h = d.heights({0.1, closed.first_contact() + closed.bounce_period() - closed.first_contact()});
    CHECK(h[0] == Approx(0.1 - 0.5 * kG * 0.01).epsilon(1e-9));
    CHECK(h[1] == Approx(0.1).epsilon(1e-4));   // RK4 at T/2e4 over 0.3 s: well below 1e-4
}

TEST_CASE("restitution with gravity and release matches docs/physics.md", "[oracle]") {
    struct Row { double zeta, e; };
    // docs/physics.md: "with gravity and a contact that releases when the force reaches zero: 0.720 at
    // ζ = 0.1, 0.527 at 0.2, 0.281 at 0.4" (three digits: half a unit of the third)
    for (Row r : {Row{0.1, 0.720}, Row{0.2, 0.527}, Row{0.4, 0.281}}) {
        INFO("zeta " << r.zeta);
        DampedDrop d{kMass, kStiff, dashpot_for_ratio(r.zeta, kStiff, kMass), kG, 0.1};
        CHECK(d.first_bounce().restitution == Approx(r.e).margin(0.5e-3));
    }
    // the release rule matters: the value without gravity and with tension, exp(−ζπ/√(1−ζ²)),
    // is 0.729 at ζ = 0.1, and the oracle must not give it
    DampedDrop d{kMass, kStiff, dashpot_for_ratio(0.1, kStiff, kMass), kG, 0.1};
    CHECK(std::abs(d.first_bounce().restitution - 0.729) > 5e-3);
    // damping lowers the peak penetration below the undamped 13.918 mm
    CHECK(d.first_bounce().max_penetration < 13.9e-3);
}

TEST_CASE("Housner's rocking block matches docs/physics.md", "[oracle]") {
    HousnerBlock b{0.35, 0.5, kG};   // reading B
    CHECK(b.alpha() == Approx(34.99 * kDeg).margin(0.005 * kDeg));
    CHECK(b.radius() == Approx(0.61033).margin(0.5e-5));
    CHECK(b.p() == Approx(3.47203).margin(0.5e-5));
    CHECK(b.first_impact(30 * kDeg) == Approx(0.76160).margin(0.5e-5));
    CHECK(b.first_impact_linear(30 * kDeg) == Approx(0.75901).margin(0.5e-5));
    CHECK(b.impact_omega(30 * kDeg) == Approx(2.0656).margin(0.5e-4));
    CHECK(b.velocity_ratio() == Approx(0.50671).margin(0.5e-5));
    CHECK(b.amplitude_after(30 * kDeg, 1) / kDeg == Approx(4.837).margin(0.5e-3));
    CHECK(b.amplitude_after(30 * kDeg, 2) / kDeg == Approx(1.183).margin(0.5e-3));
    CHECK(b.amplitude_after(30 * kDeg, 3) / kDeg == Approx(0.300).margin(0.5e-3));
    CHECK(b.amplitude_after(30 * kDeg, 1, b.velocity_ratio()) == b.amplitude_after(30 * kDeg, 1));

    HousnerBlock s{0.1, 0.5, kG};    // slender variant
    CHECK(s.alpha() == Approx(0.19740).margin(0.5e-5));
    CHECK(s.p() == Approx(3.79858).margin(0.5e-5));
    CHECK(s.first_impact(0.5 * s.alpha()) == Approx(0.34709).margin(0.5e-5));
    CHECK(s.first_impact(0.8 * s.alpha()) == Approx(0.60376).margin(0.5e-5));
    CHECK(s.velocity_ratio() == Approx(0.94231).margin(0.5e-5));
}

TEST_CASE("Housner's angle history crosses zero at t1 and keeps the amplitude its r gives", "[oracle]") {
    HousnerBlock b{0.35, 0.5, kG};
    const double th0 = 30 * kDeg, t1 = b.first_impact(th0);
    std::vector<double> t;
    for (int i = 0; i <= 30000; ++i) t.push_back(i * 1e-4);
    for (double r : {1.0, b.velocity_ratio()}) {
        INFO("r " << r);
        auto th = b.angles(th0, r, t);
        int first = -1;
        double lo = 0.0;
        for (size_t i = 1; i < th.size(); ++i) {
            if (first < 0 && th[i] <= 0.0) first = int(i);
            if (first >= 0 && t[i] < t1 + 2.0 * b.first_impact(b.amplitude_after(th0, 1, r)))
                lo = std::min(lo, th[i]);
        }
        // the integrator steps 1e-5 s, the grid is 1e-4 s
        CHECK(t[first] == Approx(t1).margin(1.1e-4));
        // the swing after the impact reaches the amplitude of the energy relation (grid-limited)
        CHECK(-lo == Approx(b.amplitude_after(th0, 1, r)).epsilon(2e-3));
    }
}

TEST_CASE("a block launched up a plane steeper than its friction angle climbs, stops and slides back down",
          "[oracle]") {
    // θ = 30°, μ = 0.4 (tan θ = 0.577 > μ), 2 m/s uphill: braked at g(sin θ + μ cos θ) = 8.3033
    // m/s² for 0.24087 s over 0.24087 m, then down at g(sin θ − μ cos θ) = 1.5018 m/s²
    const double g = 9.81, th = M_PI / 6, mu = 0.4;
    const double up = g * (std::sin(th) + mu * std::cos(th)), down = g * (std::sin(th) - mu * std::cos(th));
    const double stop = 2.0 / up, climb = 4.0 / (2 * up);
    CHECK(launched_on_incline(g, th, mu, -2.0, stop) == Approx(-climb).epsilon(1e-12));
    CHECK(launched_on_incline(g, th, mu, -2.0, stop + 1.0) == Approx(-climb + 0.5 * down).epsilon(1e-12));
    // launched down a plane flatter than its friction angle: stops after v0²/(2g(μ cos θ − sin θ))
    const double flat = 10 * M_PI / 180, brake = g * (0.6 * std::cos(flat) - std::sin(flat));
    CHECK(launched_on_incline(g, flat, 0.6, 1.5, 10.0) == Approx(1.5 * 1.5 / (2 * brake)).epsilon(1e-12));
    // at rest on it: held
    CHECK(launched_on_incline(g, flat, 0.6, 0.0, 10.0) == 0.0);
}
