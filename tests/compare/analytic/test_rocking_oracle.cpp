// the rocking oracle against Housner's free-rocking closed forms, the linearised one-sine pulse,
// energy conservation between impacts and its uplift and overturning criteria
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "analytic/rocking_oracle.hpp"
#include "analytic/rocking_oracle_pulse.hpp"
#include "error.hpp"

using namespace cairn::oracle;

namespace {
constexpr double kG = 9.81;
// the slender block of the paper's slender rocking case: 0.2 × 1.0 m across the rocking axis
const RockingOracle kSlender(0.1, 0.5, kG);

std::vector<double> grid(double t1, double dt) {
    std::vector<double> t;
    for (long i = 1; i * dt <= t1; ++i) t.push_back(double(i) * dt);
    return t;
}
}  // namespace

TEST_CASE("rocking oracle: Housner's restitution from angular momentum about the new edge", "[oracle][rocking]") {
    // a block of mass 1 rocking about its +x edge at ω hits with its −x edge; the momentum about
    // the −x edge is kept: I_c ω + m (r_c − r_new) × v_c = I_O ω'
    const double b = 0.1, h = 0.5, m = 1.0, w = -1.0;
    const double ic = m * (4 * b * b + 4 * h * h) / 12.0, io = ic + m * (b * b + h * h);
    // centre (0, h) relative to the +x pivot (b, 0): r = (−b, h); v = ω ŷ × r in the x-z plane
    const double vx = w * h, vz = w * b;   // θ̇ about the pivot, θ > 0 moving the centre to +x
    const double rx = b, rz = h;           // centre relative to the −x edge (−b, 0)
    const double momentum = ic * w + m * (rz * vx - rx * vz);
    CHECK(momentum / (io * w) == Approx(kSlender.housner_restitution()).epsilon(1e-14));
    CHECK(kSlender.housner_restitution() == Approx(1.0 - 1.5 * std::pow(std::sin(kSlender.alpha()), 2)).epsilon(1e-15));
}

TEST_CASE("rocking oracle: free rocking matches Housner's first impact and amplitudes", "[oracle][rocking]") {
    const double theta0 = 0.8 * kSlender.alpha();
    RockingOptions o;
    o.theta0 = theta0;
    o.duration = 6.0;
    o.settle = false;
    o.output_times = grid(o.duration, 1e-4);
    const auto res = kSlender.run(BaseMotion{}, o);
    REQUIRE(res.impacts >= 5);
    CHECK_FALSE(res.overturned);
    // tolerances 1e-10 per step: the event times and amplitudes are good to far better than 1e-8
    CHECK(res.impact_times[0] == Approx(kSlender.block().first_impact(theta0)).epsilon(1e-9));
    CHECK(res.impact_omega[0] == Approx(-kSlender.block().impact_omega(theta0)).epsilon(1e-9));
    for (int n = 1; n <= 5; ++n) {
        // the sampled peak between impacts n and n+1 (θ̇ = 0 there: 1e-4 s sampling is 1e-8 rad off)
        double peak = 0.0;
        for (size_t i = 0; i < o.output_times.size(); ++i)
            if (o.output_times[i] > res.impact_times[size_t(n - 1)] && o.output_times[i] < res.impact_times[size_t(n)])
                peak = std::max(peak, std::abs(res.theta[i]));
        CHECK(peak == Approx(kSlender.block().amplitude_after(theta0, n)).epsilon(1e-6));
    }
    // alternate edges: the sign of θ flips at every impact
    const auto side = [&](double t) {
        const auto it = std::lower_bound(o.output_times.begin(), o.output_times.end(), t);
        return res.theta[size_t(it - o.output_times.begin())] > 0.0;
    };
    CHECK(side(0.5 * res.impact_times[0]));
    CHECK_FALSE(side(0.5 * (res.impact_times[0] + res.impact_times[1])));
}

TEST_CASE("rocking oracle: the linearised free block follows α − (α − θ0) cosh pt", "[oracle][rocking]") {
    const double a = kSlender.alpha(), p = kSlender.p(), theta0 = 0.5 * a;
    RockingOptions o;
    o.theta0 = theta0;
    o.linear = true;
    o.duration = 2.0;
    o.settle = false;
    o.output_times = {0.013, 0.1, 0.2345, 0.3, 0.4};   // between steps: the dense output
    const auto res = kSlender.run(BaseMotion{}, o);
    REQUIRE(res.impacts >= 1);
    CHECK(res.impact_times[0] == Approx(kSlender.block().first_impact_linear(theta0)).epsilon(1e-9));
    for (size_t i = 0; i < o.output_times.size(); ++i) {
        if (o.output_times[i] >= res.impact_times[0]) break;
        // Hairer's 4th-order interpolant at tolerance 1e-10: better than 1e-9 rad
        CHECK(res.theta[i] == Approx(a - (a - theta0) * std::cosh(p * o.output_times[i])).margin(1e-9));
    }
}

TEST_CASE("rocking oracle: energy is conserved between impacts and scaled by r² at each", "[oracle][rocking]") {
    const double theta0 = 0.9 * kSlender.alpha();
    const double r = 0.8;   // a given restitution, not Housner's
    RockingOptions o;
    o.theta0 = theta0;
    o.restitution = r;
    o.duration = 3.0;
    o.settle = false;
    o.output_times = grid(o.duration, 1e-3);
    const auto res = kSlender.run(BaseMotion{}, o);
    REQUIRE(res.impacts >= 3);
    const double e0 = kSlender.energy(theta0, 0.0);
    size_t next = 0;
    double level = e0, worst = 0.0;
    for (size_t i = 0; i < o.output_times.size(); ++i) {
        while (next < res.impact_times.size() && o.output_times[i] > res.impact_times[next]) {
            level *= r * r;   // all kinetic at θ = 0: the impact keeps r² of it
            ++next;
        }
        worst = std::max(worst, std::abs(kSlender.energy(res.theta[i], res.omega[i]) / level - 1.0));
    }
    // per-step tolerance 1e-10 over a few hundred steps
    CHECK(worst < 1e-8);
    for (size_t n = 0; n < 3; ++n)   // the kinetic energy at each impact
        CHECK(0.5 * std::pow(res.impact_omega[n], 2) == Approx(e0 * std::pow(r, 2.0 * double(n))).epsilon(1e-8));
}

TEST_CASE("rocking oracle: the linearised block under a one-sine pulse matches the closed form", "[oracle][rocking]") {
    const double a = kSlender.alpha(), p = kSlender.p();
    for (const double ratio : {1.0, 3.0, 6.0}) {          // ω_p / p
        for (const double level : {1.2, 2.0, 4.0}) {      // a_p / (g α)
            const Pulse pulse{PulseShape::sine, level * kG * a, ratio * p};
            RockingOptions o;
            o.linear = true;
            o.duration = 4.0 * pulse.duration();
            o.settle = false;
            const LinearSinePulse closed{p, a, kG, pulse.amplitude, pulse.omega};
            o.output_times = grid(o.duration, pulse.duration() / 97.0);
            const auto res = kSlender.run(pulse.motion(), o);
            REQUIRE(!res.uplift_times.empty());
            // the uplift root is bisected on the pulse itself: to machine precision
            CHECK(res.uplift_times[0] == Approx(closed.uplift_time()).epsilon(1e-12));
            const double until = std::min({res.impact_times.empty() ? o.duration : res.impact_times[0],
                                           res.overturned ? res.overturn_time : o.duration});
            int compared = 0;
            for (size_t i = 0; i < o.output_times.size() && o.output_times[i] < until; ++i) {
                if (o.output_times[i] < closed.uplift_time()) continue;
                const auto s = closed.state(o.output_times[i]);
                // tolerance 1e-10 per step with cosh growth e^{pt} ≤ e^{8}: within 1e-8 rad
                CHECK(res.theta[i] == Approx(s[0]).margin(1e-8));
                ++compared;
            }
            CHECK(compared > 10);
        }
    }
}

TEST_CASE("rocking oracle: a slender block is close to the linearised closed form", "[oracle][rocking]") {
    // α = 0.04: sin x → x and cos x → 1 are off by x²/6 and x²/2 of the terms, x ≤ 2α; the
    // response stays within 1 % of α of the closed form while |θ| < α
    const RockingOracle slim(0.02, 0.5, kG);
    const double a = slim.alpha(), p = slim.p();
    const Pulse pulse{PulseShape::sine, 2.0 * kG * a, 3.0 * p};
    const LinearSinePulse closed{p, a, kG, pulse.amplitude, pulse.omega};
    RockingOptions o;
    o.duration = 2.0 * pulse.duration();
    o.settle = false;
    o.output_times = grid(o.duration, pulse.duration() / 50.0);
    const auto res = slim.run(pulse.motion(), o);
    const double until = res.impact_times.empty() ? o.duration : res.impact_times[0];
    int compared = 0;
    for (size_t i = 0; i < o.output_times.size() && o.output_times[i] < until; ++i) {
        if (o.output_times[i] < closed.uplift_time() + 1e-3) continue;
        CHECK(std::abs(res.theta[i] - closed.state(o.output_times[i])[0]) < 0.01 * a);
        ++compared;
    }
    CHECK(compared > 10);
}

TEST_CASE("rocking oracle: uplift at (g + a_v) tan α, located exactly", "[oracle][rocking]") {
    const double a = kSlender.alpha(), k = 2.0;   // a_g = k t, m/s³
    for (const double av : {0.0, 2.0, -3.0}) {
        BaseMotion m;
        m.horizontal = [k](double t) { return k * t; };
        m.vertical = [av](double) { return av; };
        m.end = 5.0;
        RockingOptions o;
        o.duration = 5.0;
        const auto res = kSlender.run(m, o);
        REQUIRE(!res.uplift_times.empty());
        CHECK(res.uplift_times[0] == Approx((kG + av) * std::tan(a) / k).epsilon(1e-12));
    }
    // a constant a_g just below the threshold never lifts the block
    BaseMotion below;
    const double just = 0.999 * kG * std::tan(a);
    below.horizontal = [just](double) { return just; };
    below.end = 2.0;
    RockingOptions o;
    o.duration = 2.0;
    const auto res = kSlender.run(below, o);
    CHECK(res.uplift_times.empty());
    CHECK(res.max_abs_theta == 0.0);
}

TEST_CASE("rocking oracle: overturning is |θ| reaching π/2, past α the block can still return", "[oracle][rocking]") {
    const double a = kSlender.alpha(), p = kSlender.p();
    const double hill = kSlender.energy(a, 0.0), theta0 = 0.5 * a;
    const double v0 = kSlender.energy(theta0, 0.0);
    RockingOptions o;
    o.theta0 = theta0;
    o.duration = 20.0;
    o.omega0 = std::sqrt(2.0 * (hill * 1.001 - v0));   // just over the hill: falls
    auto res = kSlender.run(BaseMotion{}, o);
    CHECK(res.overturned);
    CHECK(res.stop == "overturned");
    CHECK(res.exceed_time > 0.0);
    CHECK(res.overturn_time > res.exceed_time);
    o.omega0 = std::sqrt(2.0 * (hill * 0.999 - v0));   // just under: rocks and settles
    res = kSlender.run(BaseMotion{}, o);
    CHECK_FALSE(res.overturned);
    CHECK(res.exceed_time < 0.0);
    CHECK(res.stop == "settled");
    // past α but pulled back: a block moving out past α under a strong opposite base acceleration
    BaseMotion back;
    back.horizontal = [](double) { return 1.0 * kG; };   // pushes θ towards −x, i.e. back
    back.end = 0.15;
    o.omega0 = std::sqrt(2.0 * (hill * 1.05 - v0));
    res = kSlender.run(back, o);
    CHECK(res.exceed_time > 0.0);
    CHECK_FALSE(res.overturn_time == Approx(res.exceed_time));
    CHECK(res.max_abs_theta > a);
    CHECK(res.impacts >= 1);   // it came back through θ = 0
    (void)p;
}

TEST_CASE("rocking oracle: a stronger one-sine pulse overturns a block a weaker spares", "[oracle][rocking]") {
    const double a = kSlender.alpha(), p = kSlender.p();
    const double w = 6.0 * p;
    RockingOptions o;
    o.duration = 20.0;
    // at ω_p/p = 6 the rigid block overturns from about 4.7 g·tan α on (the overturning spectrum
    // of the one-sine pulse), and a stronger pulse past about 9 g·tan α is safe again: the block is
    // thrown one way, hits, and the second half-cycle stops it (the two overturning modes)
    const auto weak = kSlender.run(Pulse{PulseShape::sine, 2.0 * kG * std::tan(a), w}.motion(), o);
    const auto strong = kSlender.run(Pulse{PulseShape::sine, 6.0 * kG * std::tan(a), w}.motion(), o);
    const auto stronger = kSlender.run(Pulse{PulseShape::sine, 15.0 * kG * std::tan(a), w}.motion(), o);
    CHECK_FALSE(weak.overturned);
    CHECK(weak.stop == "settled");
    CHECK(strong.overturned);
    CHECK_FALSE(stronger.overturned);
}

TEST_CASE("rocking oracle: bad input is refused", "[oracle][rocking]") {
    CHECK_THROWS_AS(RockingOracle(0.0, 0.5, kG), cairn::Error);
    RockingOptions o;
    o.theta0 = 1.0;   // past α
    CHECK_THROWS_AS(kSlender.run(BaseMotion{}, o), cairn::Error);
    BaseMotion lift;
    lift.vertical = [](double) { return -2.0 * kG; };
    lift.end = 1.0;
    CHECK_THROWS_AS(kSlender.run(lift, RockingOptions{}), cairn::Error);
    CHECK_THROWS_AS(parse_pulse_shape("square"), cairn::Error);
}
