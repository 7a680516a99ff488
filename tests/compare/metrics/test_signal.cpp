// signal tools on synthetic signals with known answers
#include <catch2/catch.hpp>

#include <cmath>

#include "metrics/signal.hpp"

using namespace cairn::metrics;

namespace {
Series sample(double t0, double t1, double dt, double (*f)(double)) {
    Series s;
    for (double t = t0; t <= t1 + 1e-12; t += dt) { s.t.push_back(t); s.y.push_back(f(t)); }
    return s;
}
constexpr double kPeriod = 0.058493;   // stability period of docs/physics.md
double swing(double t) { return 8.502e-4 * (1.0 - std::cos(2.0 * M_PI * t / kPeriod)); }
double parabola(double t) { return 0.3 + 0.2 * t + 0.5 * 0.981 * t * t; }
}  // namespace

TEST_CASE("the period of a sampled cosine comes from its crossings", "[metrics]") {
    // 1.1 ms samples (dem's step on the stability scene): linear interpolation of a crossing of a
    // sine is exact to O(dt³) per crossing; the period averages them
    Series s = sample(0.0, 0.5, 1.1e-3, swing);
    CHECK(period_from_crossings(s, 8.502e-4) == Approx(kPeriod).epsilon(1e-4));
    auto c = crossings(s, 8.502e-4, Crossing::up);
    REQUIRE(c.size() >= 2);
    CHECK(c[0] == Approx(0.25 * kPeriod).epsilon(1e-4));
    CHECK(crossings(s, 8.502e-4, Crossing::down)[0] == Approx(0.75 * kPeriod).epsilon(1e-4));
}

TEST_CASE("extrema are refined by the parabola through three samples", "[metrics]") {
    Series s = sample(0.0, 0.2, 1.1e-3, swing);
    auto peaks = extrema(s, true, 1e-4);
    REQUIRE(peaks.size() == 3);   // peaks at T/2, 3T/2, 5T/2 < 0.2 s
    // a cosine near its top is a parabola to O(dt⁴): the vertex is within 1e-5 of the period
    CHECK(peaks[0].t == Approx(0.5 * kPeriod).margin(1e-5 * kPeriod * 100));
    CHECK(peaks[0].y == Approx(2.0 * 8.502e-4).epsilon(1e-4));
    auto valleys = extrema(s, false, 1e-4);
    REQUIRE(valleys.size() >= 3);
    CHECK(valleys[0].t == Approx(kPeriod).epsilon(1e-3));
    CHECK(valleys[0].y == Approx(0.0).margin(1e-9));
    // a small wiggle below the prominence is no extremum
    CHECK(extrema(s, true, 1.0).empty());
}

TEST_CASE("a quadratic fit recovers the acceleration of a parabola", "[metrics]") {
    Series s = sample(0.0, 1.0, 7.8e-4, parabola);
    auto c = polyfit(s, 2, 0.1, 1.0);
    // exact data: only rounding errors remain
    CHECK(2.0 * c[2] == Approx(0.981).epsilon(1e-9));
    CHECK(c[1] == Approx(0.2).epsilon(1e-9));
    CHECK(c[0] == Approx(0.3).epsilon(1e-9));
}

TEST_CASE("interpolation, means and shifted differences", "[metrics]") {
    Series s = sample(0.0, 0.5, 1e-3, swing);
    // linear between 1 ms samples: error ≤ (dt ω)²/8 of the amplitude ≈ 1.4e-3 at most, far less here
    CHECK(interpolate(s, 0.25 * kPeriod) == Approx(8.502e-4).epsilon(1e-4));
    // the mean over whole periods is the midline; the trapezoid rule on 58 points per period is
    // exact for a sine over whole periods up to the end effects of a partial interval
    CHECK(mean_value(s, 0.0, 5 * kPeriod) == Approx(8.502e-4).epsilon(1e-3));
    CHECK(max_value(s) <= 2.0 * 8.502e-4);
    CHECK(min_value(s) >= 0.0);
    // a copy delayed by 5 ms differs from the original, and not once the shift is taken out
    Series late = s;
    for (double& t : late.t) t += 5e-3;
    CHECK(rms_difference(late, s, 0.0) > 1e-4);
    CHECK(rms_difference(late, s, 5e-3) == Approx(0.0).margin(1e-12));
}

namespace {
// a held block's base: 40 µm of elastic shear, a 0.356 s rocking swing of ±8 µm (the 0.5 m cube
// under 0.45 W at its top on dem's springs) and a creep of `rate` m/s
double held_base(double t, double rate, double phase) {
    return 4e-5 + 8e-6 * std::sin(2.0 * M_PI * t / 0.356 + phase) + rate * t;
}
Series held_series(double rate, double phase, double t1) {
    Series s;
    for (double t = 0.0; t <= t1 + 1e-12; t += 1e-3) s.t.push_back(t), s.y.push_back(held_base(t, rate, phase));
    return s;
}
}  // namespace

TEST_CASE("held drift: the ringing of a held block is taken out, a creep is not", "[metrics]") {
    // a straight line through 2.1 periods of the swing tilts by up to ~0.4 of its amplitude,
    // depending on where the window cuts it; the lines through the turning points do not
    for (double phase : {0.0, 1.0, 2.0, 3.0, 4.0, 5.0}) {
        INFO("phase " << phase);
        const Series still = held_series(0.0, phase, 2.0);
        const auto d = held_drift(still, 1.25, 2.0, 1e-7);
        REQUIRE(d.resolved);
        // the turning points are parabola-refined to far below 1 nm on 1 ms samples
        CHECK(std::abs(d.drift) < 2e-9);
        CHECK(d.ringing == Approx(8e-6).epsilon(1e-3));
        // a creep of 2 µm/s: 1.5 µm over the 0.75 s window, whatever the phase (2e-3: the drift
        // is over the samples in the window, whose ends fall within 1 ms of its bounds)
        const auto c = held_drift(held_series(2e-6, phase, 2.0), 1.25, 2.0, 1e-7);
        REQUIRE(c.resolved);
        CHECK(c.drift == Approx(1.5e-6).epsilon(2e-3));
    }
    // the straight-line fit alone is fooled by the swing: the reason for the turning points
    double worst = 0.0;
    for (double phase : {0.0, 1.0, 2.0, 3.0, 4.0, 5.0})
        worst = std::max(worst, std::abs(polyfit(held_series(0.0, phase, 2.0), 1, 1.25, 2.0)[1] * 0.75));
    CHECK(worst > 2e-6);
    // no swing above the noise: the straight-line fit, exact on a line
    Series ramp;
    for (double t = 0.0; t <= 2.0; t += 1e-3) ramp.t.push_back(t), ramp.y.push_back(3e-6 * t);
    const auto r = held_drift(ramp, 1.0, 2.0, 1e-7);
    CHECK(r.resolved);
    CHECK(r.drift == Approx(3e-6).epsilon(1e-9));
    CHECK(r.ringing < 1e-15);
    // a swing slower than the window: fewer than two turning points of each kind, not resolved
    Series slow;
    for (double t = 0.0; t <= 2.0; t += 1e-3) slow.t.push_back(t), slow.y.push_back(1e-5 * std::sin(2.0 * M_PI * t / 1.5));
    CHECK_FALSE(held_drift(slow, 1.25, 2.0, 1e-7).resolved);
}

TEST_CASE("held drift: a fast ringing on a forced swing does not pass for turning points", "[metrics]") {
    // a 0.4 m cube held by dem's springs under a circular ground motion at 2 Hz: its centre of
    // mass swings ±1.2 µm with the drive, and its undamped springs ring ±10 nm at 830 Hz on top
    // (170 Hz once sampled every 1 ms); its mean place is steady. The small wiggles rise above the
    // noise, but turning points are only those of the swing that carries the signal
    for (double phase : {0.0, 1.0, 2.0, 3.0}) {
        INFO("phase " << phase);
        Series s;
        for (double t = 0.0; t <= 5.0 + 1e-12; t += 1e-3)
            s.t.push_back(t),
                s.y.push_back(1.2e-6 * std::sin(4.0 * M_PI * t + phase) + 1e-8 * std::sin(2.0 * M_PI * 830.0 * t));
        // the swings' turns: one maximum and one minimum a period, none of the wiggles
        const auto turns = swings(s, 1e-7);
        CHECK(turns.maxima.size() == 10);
        CHECK(turns.minima.size() == 10);
        for (const auto& e : turns.maxima) CHECK(e.y == Approx(1.2e-6).epsilon(0.02));
        const auto d = held_drift(s, 2.5, 5.0, 3.8e-9);
        REQUIRE(d.resolved);
        // the turning points of the swing carry the ±10 nm wiggle: 2 % of the swing
        CHECK(std::abs(d.drift) < 2.5e-8);
        CHECK(d.ringing == Approx(1.2e-6).epsilon(0.02));
    }
}

TEST_CASE("held drift: a swing forced by a record is not read as a drift, a decaying ringing is", "[metrics]") {
    // a held block under a record: it follows the drive to either side and back, its swings
    // growing and dying with the record (two bursts of different sizes and signs), about a steady
    // mean. Lines through its turning points would slope with the bursts' envelope: not resolved
    Series forced;
    for (double t = 0.0; t <= 2.0 + 1e-12; t += 1e-3) {
        const double burst = 2e-6 * std::exp(-std::pow((t - 1.2) / 0.1, 2)) - 1.5e-6 * std::exp(-std::pow((t - 1.6) / 0.08, 2));
        forced.t.push_back(t), forced.y.push_back(burst + 1e-7 * std::sin(2 * M_PI * 40.0 * t));
    }
    const auto f = held_drift(forced, 1.0, 2.0, 4e-9);
    CHECK_FALSE(f.resolved);
    CHECK(f.unsteady);
    CHECK(f.ringing > 1e-6);   // the largest swing about a straight line, as reported
    // a ringing that decays (ζ = 0.05 at 6 Hz) about a steady mean is resolved, with no drift read
    // into it, and a creep under it is read (1e-2: the decay tilts the turning points' lines
    // alike, and their mean slope leaves a part of a per cent)
    for (const double rate : {0.0, 2e-6}) {
        Series decay;
        for (double t = 0.0; t <= 2.0 + 1e-12; t += 1e-3)
            decay.t.push_back(t), decay.y.push_back(5e-6 * std::exp(-0.05 * 2 * M_PI * 6.0 * t) * std::cos(2 * M_PI * 6.0 * t) + rate * t);
        const auto d = held_drift(decay, 1.0, 2.0, 4e-9);
        INFO("creep rate " << rate);
        REQUIRE(d.resolved);
        CHECK_FALSE(d.unsteady);
        CHECK(d.drift == Approx(rate * 1.0).margin(2e-2 * 5e-6 * std::exp(-0.05 * 2 * M_PI * 6.0)));
    }
    // a ringing that dies within the window's first third (ζ = 0.05 at 20 Hz from its start, the
    // onset of a held pulse: earthquake/block_pulse_hold on dem), its turns all early: the lines
    // through them, extrapolated to the window's middle, cross there; the ringing is taken where
    // the turns are, and little drift is read into it (a fifth of the ringing at the window's
    // start: straight lines through an exponential decay's maxima and minima tilt unequally, by
    // the part of the decay that falls in half a period, 16 % here; measured 14 %)
    Series dying;
    for (double t = 0.0; t <= 2.0 + 1e-12; t += 1e-3)
        dying.t.push_back(t), dying.y.push_back(3.5e-5 + 2e-6 * std::exp(-0.05 * 2 * M_PI * 20.0 * t) * std::cos(2 * M_PI * 20.0 * t));
    const auto d = held_drift(dying, 1.0, 2.0, 1e-11);
    CHECK(d.resolved);
    CHECK(d.ringing > 0.0);
    CHECK(std::abs(d.drift) < 0.2 * 2e-6 * std::exp(-0.05 * 2 * M_PI * 20.0));
}
