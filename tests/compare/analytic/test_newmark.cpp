// Newmark's sliding block against closed forms worked by hand: a rectangular pulse, the same pulse
// turned in the plane, a vertical component that changes the friction, a drive inside the disk
#include <catch2/catch.hpp>

#include <cmath>

#include "analytic/newmark.hpp"

using namespace cairn;
using namespace cairn::oracle;

namespace {

constexpr double kG = 9.81;

/// a rectangular pulse of `a` (m/s²) along `dir` from t0 to t1 (s), plus a constant vertical f_z
std::function<Vec3(double)> pulse(double a, const Vec3& dir, double t0, double t1, double fz = 0.0) {
    return [=](double t) { return Vec3((t >= t0 && t < t1 ? a : 0.0) * dir + Vec3(0, 0, fz)); };
}

/// the rectangular pulse's slide: (a − μn)·T²/2 during it, then braked at μn from (a − μn)·T
double rectangular_slide(double a, double mu_n, double T) {
    const double v = (a - mu_n) * T;
    return 0.5 * (a - mu_n) * T * T + v * v / (2.0 * mu_n);
}

}  // namespace

TEST_CASE("newmark: a rectangular pulse beyond friction slides the closed-form distance", "[oracle][newmark]") {
    // 0.8 g for 0.3 s at μ = 0.6: 0.08829 m in the pulse, 0.02943 m braking, 0.11772 m
    const double exact = rectangular_slide(0.8 * kG, 0.6 * kG, 0.3);
    CHECK(exact == Approx(0.11772).margin(1e-9));
    const auto h = newmark_slide(pulse(0.8 * kG, Vec3::UnitX(), 0.2, 0.5), kG, 0.6, 1.0);
    // steps of 1e-5 s: the pulse's edges fall within a step, O(h·a) on the velocity, so O(h/T)
    // = 3e-5 relative on the slide
    CHECK(h.x.back().x() == Approx(exact).epsilon(1e-4));
    CHECK(std::abs(h.x.back().y()) < 1e-12);
    CHECK(h.onsets == 1);
    CHECK(h.slide_time == Approx(0.4).epsilon(1e-4));   // 0.3 s of pulse, then (a − μg)T/(μg) = 0.1 s
    CHECK(h.peak_ratio == Approx(0.8).epsilon(1e-12));
    // at rest before the pulse and after the stop
    CHECK(h.at(0.19).norm() == 0.0);
    CHECK(h.at(0.7).x() == Approx(h.at(0.95).x()).epsilon(1e-12));
}

TEST_CASE("newmark: the friction disk is round, the pulse turned in the plane slides as far", "[oracle][newmark]") {
    const double exact = rectangular_slide(0.8 * kG, 0.6 * kG, 0.3);
    for (double deg : {30.0, 45.0, 117.0}) {
        CAPTURE(deg);
        const Vec3 dir(std::cos(deg * M_PI / 180.0), std::sin(deg * M_PI / 180.0), 0.0);
        const auto h = newmark_slide(pulse(0.8 * kG, dir, 0.2, 0.5), kG, 0.6, 1.0);
        CHECK(h.x.back().norm() == Approx(exact).epsilon(1e-4));
        // straight along the drive: the sideways part is rounding
        CHECK(std::abs(h.x.back().x() * dir.y() - h.x.back().y() * dir.x()) < 1e-9);
    }
}

TEST_CASE("newmark: a vertical drive changes the friction, n = g − f_z", "[oracle][newmark]") {
    // the ground accelerating up at 0.2 g pushes the block down (f_z = −0.2 g): μ·1.2 g = 0.72 g
    const auto down = newmark_slide(pulse(0.8 * kG, Vec3::UnitX(), 0.0, 0.3, -0.2 * kG), kG, 0.6, 1.0);
    CHECK(down.x.back().x() == Approx(rectangular_slide(0.8 * kG, 0.72 * kG, 0.3)).epsilon(1e-4));
    // accelerating down at 0.2 g: μ·0.8 g = 0.48 g
    const auto up = newmark_slide(pulse(0.8 * kG, Vec3::UnitX(), 0.0, 0.3, 0.2 * kG), kG, 0.6, 1.0);
    CHECK(up.x.back().x() == Approx(rectangular_slide(0.8 * kG, 0.48 * kG, 0.3)).epsilon(1e-4));
    // beyond g the block floats: no friction, x = f t²/2
    const auto free = newmark_slide([](double) { return Vec3(1.0, 0.0, 1.5 * kG); }, kG, 0.6, 0.5);
    CHECK(free.x.back().x() == Approx(0.125).epsilon(1e-9));
}

TEST_CASE("newmark: a drive inside the friction disk never moves the block", "[oracle][newmark]") {
    // 0.59 g constant, then a 0.45 g pulse, then an oscillation of 0.599 g: all below μg = 0.6 g
    auto drive = [](double t) {
        if (t < 0.3) return Vec3(0.59 * kG, 0, 0);
        if (t < 0.6) return Vec3(0, 0.45 * kG, 0);
        return Vec3(0.599 * kG * std::sin(20.0 * t), 0, 0);
    };
    const auto h = newmark_slide(drive, kG, 0.6, 2.0);
    CHECK(h.x.back().norm() == 0.0);
    CHECK(h.onsets == 0);
    CHECK(h.slide_time == 0.0);
}

TEST_CASE("newmark: a pulse each way slides back, and the stop between is found", "[oracle][newmark]") {
    // +0.8 g for 0.3 s, then −0.8 g for 0.3 s: the first slides out and is braked by friction and
    // the reversed drive (μg + 0.8 g) from (a − μg)T: it stops 0.0421 s into the second pulse
    // (v/(1.4 g)), then slides back under (0.8 − 0.6) g for the remaining 0.2579 s and is braked
    const double a = 0.8 * kG, f = 0.6 * kG, T = 0.3;
    const double v1 = (a - f) * T, x1 = 0.5 * (a - f) * T * T;
    const double ts = v1 / (a + f), xs = x1 + 0.5 * v1 * ts;
    const double tb = T - ts, v2 = (a - f) * tb;
    const double back = 0.5 * (a - f) * tb * tb + v2 * v2 / (2.0 * f);
    auto drive = [=](double t) { return Vec3(t < T ? a : (t < 2 * T ? -a : 0.0), 0, 0); };
    const auto h = newmark_slide(drive, kG, 0.6, 1.5);
    CHECK(h.onsets == 2);
    CHECK(h.x.back().x() == Approx(xs - back).epsilon(1e-4));
}

TEST_CASE("newmark: any duration is integrated in at most 2e6 steps", "[oracle][newmark]") {
    const auto h = newmark_slide([](double) { return Vec3(0.1, 0, 0); }, kG, 0.0, 1e7);
    CHECK(h.t.size() <= 2000001);
    CHECK(h.t.back() == Approx(1e7));
    CHECK(h.x.back().x() == Approx(0.5 * 0.1 * 1e14).epsilon(1e-9));
}

TEST_CASE("newmark: a block launched along the base stops after v0²/(2μg), and a push along helps it on",
          "[oracle][newmark]") {
    const auto none = [](double) { return Vec3::Zero(); };
    // 2 m/s at 30° in the plane, μ = 0.5: 0.4077 m along its launch, stopped at v0/(μg) = 0.408 s
    const Vec2 v0 = 2.0 * Vec2(std::cos(M_PI / 6), std::sin(M_PI / 6));
    const auto h = newmark_slide(none, kG, 0.5, 1.0, v0);
    const double stop = 4.0 / (2 * 0.5 * kG);
    // the stop found within its step (1e-5 s): O(h·v) = 2e-5 m
    CHECK(h.x.back().norm() == Approx(stop).margin(2e-5));
    CHECK(h.x.back().normalized().dot(v0.normalized()) == Approx(1.0).epsilon(1e-12));
    CHECK(h.slide_time == Approx(2.0 / (0.5 * kG)).margin(2e-5));
    CHECK(h.onsets == 1);
    // a constant push of 0.3 g along the launch, below μ: braked at (μ − 0.3)g, then holds
    const auto push = [](double) { return Vec3(0.3 * kG, 0, 0); };
    const auto p = newmark_slide(push, kG, 0.5, 2.0, Vec2(2.0, 0.0));
    CHECK(p.x.back().x() == Approx(4.0 / (2 * 0.2 * kG)).margin(2e-5));
}
