// ground motion on every backend through the same body loads: a vertical sine below g keeps a
// block in contact and its relative motion follows the penalty spring's closed form; above g it
// lifts off when a_z first passes −g; a y record moves a block as the x record rotated
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <sstream>

#include "engine_scenes.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

constexpr double g = 9.81;
constexpr double kPi = 3.14159265358979323846;

// a 1 m stone cube (2600 kg) on a fixed 3 × 3 × 1 m base, kn = ks = 3e7 N/m³, no damping, placed at
// its static penetration `pen` (m), under a sine of amplitude `amp` (m/s²) and frequency `hz`
// along world axis `axis` ("x", "y", "z"), sampled every 2.5 ms
Scene sine_scene(const std::string& axis, double amp, double hz, double pen, double friction) {
    std::ostringstream t, a;
    for (int i = 0; i <= 800; ++i) {
        const double ti = 0.0025 * i;
        t << (i ? ", " : "") << ti;
        a << (i ? ", " : "") << amp * std::sin(2 * kPi * hz * ti);
    }
    std::ostringstream s;
    s.precision(17);
    s << "[run]\nduration = 2.0\ndt = 1e-4\n[materials.stone]\ndensity = 2600\nyoung = 30e9\npoisson = 0.2\n"
      << "[contact]\nkn = 3e7\nks = 3e7\nfriction = " << friction << "\n"
      << "[blocks.A]\nsize = [1, 1, 1]\nposition = [0, 0, " << 0.5 - pen << "]\nmaterial = \"stone\"\n"
      << "[blocks.B]\nsize = [3, 3, 1]\nposition = [0, 0, -0.5]\nmaterial = \"stone\"\nfixed = true\n"
      << "[ground_motion.z]\ntime = [0, 1]\nacceleration = [0, 0]\nunits = \"m/s2\"\n"   // replaced below
      ;
    std::string text = s.str();
    text.replace(text.find("[ground_motion.z]"), std::string::npos,
                 "[ground_motion." + axis + "]\ntime = [" + t.str() + "]\nacceleration = [" + a.str() +
                     "]\nunits = \"m/s2\"\n");
    return parse_scene(text, "<ground sine " + axis + ">");
}

// step `engine` (matched contact: the penalty spring kn·A on every backend that has one; the
// scenes start at the spring's static sink, which a rigid-only engine such as siconos cannot
// take) and call `each`
void run(const std::string& engine, const Scene& scene, double duration, const std::function<void(const Sample&)>& each) {
    auto backend = build_backend(engine, scene, "matched");
    const long long steps = std::llround(duration / backend->time_step());
    for (long long i = 0; i < steps; ++i) {
        if (backend->step() != StepStatus::ok) FAIL(engine << " unstable: " << backend->failure());
        each(backend->sample());
    }
}

}  // namespace

TEST_CASE("every backend: a vertical sine below g keeps contact, the spring follows the closed form", "[engines][ground]") {
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    CAPTURE(engine);
    // k = kn·A = 3e7 N/m, m = 2600 kg: ωn = 107.4 rad/s; forcing 1 Hz at 0.5 g, r = ω/ωn = 0.0585
    const double m = 2600.0, k = 3e7, wn = std::sqrt(k / m), w = 2 * kPi * 1.0, r = w / wn, amp = 0.5 * g;
    const double pen = m * g / k;   // 8.502e-4 m
    // relative displacement from rest under −m·a_z, undamped, from rest at t = 0:
    // u(t) = −(m·amp/k)·(sin ωt − r sin ωn t)/(1 − r²)
    const double x0 = m * amp / k / (1 - r * r);
    double worst = 0.0, lowest_gap = 1.0, highest_gap = -1.0;
    run(engine, sine_scene("z", amp, 1.0, pen, 0.6), 2.0, [&](const Sample& s) {
        const double u = s.blocks[0].position.z() - (0.5 - pen);
        const double exact = -x0 * (std::sin(w * s.t) - r * std::sin(wn * s.t));
        worst = std::max(worst, std::abs(u - exact));
        const double gap = s.blocks[0].position.z() - 0.5;
        lowest_gap = std::min(lowest_gap, gap);
        highest_gap = std::max(highest_gap, gap);
    });
    WARN(engine << ": largest miss of the closed form " << worst << " m of amplitude " << x0 << " m; gap "
                << lowest_gap << " to " << highest_gap << " m");
    // in contact throughout: the bottom never rises above the base (the spring stays compressed,
    // m(g + a_z) ≥ m g/2 > 0)
    CHECK(highest_gap < 0.0);
    // the closed form within 10 % of its amplitude: the engines' velocity-level springs damp the
    // free part r·x0 (6 % of it) that the closed form keeps undamped (measured: dem 7e-5 of x0,
    // the engines 2.5-4 %)
    CHECK(worst < 0.1 * x0);
}

TEST_CASE("every backend: a vertical sine above g lifts the block off when a_z passes -g", "[engines][ground]") {
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    CAPTURE(engine);
    const double amp = 1.5 * g, w = 2 * kPi;
    // separation when amp·sin ωt = −g: t_s = (π + asin(1/1.5))/ω = 0.6161 s; after it the relative
    // acceleration −g − a_z grows as j·(t − t_s), j = amp·ω·|cos ωt_s|, so the gap reaches 1 mm
    // at Δt = (6·1e-3/j)^(1/3)
    const double ts = (kPi + std::asin(1 / 1.5)) / w;
    const double j = amp * w * std::abs(std::cos(w * ts));
    const double t_mm = ts + std::cbrt(6e-3 / j);
    double first = -1.0;
    run(engine, sine_scene("z", amp, 1.0, 2600.0 * g / 3e7, 0.6), 0.8, [&](const Sample& s) {
        if (first < 0 && s.blocks[0].position.z() - 0.5 > 1e-3) first = s.t;
    });
    WARN(engine << ": gap of 1 mm at " << first << " s, closed form " << t_mm << " s");
    // 5 ms: the spring's unloading and the sampling of the record (2.5 ms) shift the start
    // (measured: 0.7-1.9 ms late)
    CHECK(first == Approx(t_mm).margin(0.005));
}

TEST_CASE("every backend: a y record moves a block as the x record rotated", "[engines][ground]") {
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    CAPTURE(engine);
    // 0.8 g at 1 Hz against μ = 0.3: the block slides back and forth
    std::vector<double> along_x, along_y, across;
    const double pen = 2600.0 * g / 3e7;
    run(engine, sine_scene("x", 0.8 * g, 1.0, pen, 0.3), 1.0, [&](const Sample& s) {
        along_x.push_back(s.blocks[0].position.x());
        across.push_back(s.blocks[0].position.y());
    });
    run(engine, sine_scene("y", 0.8 * g, 1.0, pen, 0.3), 1.0, [&](const Sample& s) {
        along_y.push_back(s.blocks[0].position.y());
        across.push_back(s.blocks[0].position.x());
    });
    REQUIRE(along_x.size() == along_y.size());
    double peak = 0.0, worst = 0.0, drift = 0.0;
    for (size_t i = 0; i < along_x.size(); ++i) {
        peak = std::max(peak, std::abs(along_x[i]));
        worst = std::max(worst, std::abs(along_x[i] - along_y[i]));
    }
    for (double c : across) drift = std::max(drift, std::abs(c));
    WARN(engine << ": slid " << peak << " m; x and y runs differ by " << worst << " m, cross drift " << drift << " m");
    CHECK(peak > 0.05);   // it did slide: (0.8 − 0.3) g over a half period is metres of travel
    // 1e-4 of the travel: the engines' contact points and solver order are not exactly symmetric
    // in x and y (measured: dem and MuJoCo to rounding, Bullet and ODE 3e-6 and 1.3e-5 of it)
    CHECK(worst < 1e-4 * peak);
    CHECK(drift < 1e-4 * peak);
}
