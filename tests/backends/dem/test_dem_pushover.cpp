// Pushover of the shipped column and wall scenes on dem: they overturn as one body at the a/g of
// the rigid limit analysis, plus the ramp's lag (compare/analytic), within 2 %.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "cases/case_analysis.hpp"
#include "dem_test_util.hpp"
#include "run/energy_scale.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

namespace {

// the bound of issue 11 on a shipped scene's energy balance: 0.1 % of the motion energy
constexpr double kClosure = 1e-3;

// largest |balance error| / motion energy over the samples, as the runner judges it
double max_balance_error(const Scene& s, const std::vector<Sample>& samples) {
    EnergyScale scale(s);
    const double e0 = samples.front().energy.total();
    double worst = 0.0;
    for (const auto& x : samples)
        worst = std::max(worst, std::abs(x.energy.total() - e0) / scale.add(x.energy).motion);
    return worst;
}

// run the shipped scene on dem, keeping a sample per output interval, and analyse it; `balance`
// gets the run's largest balance error relative to the motion energy
cases::CaseAnalysis pushover(const std::string& name, bool& completed,
                             const std::vector<Override>& overrides = {}, double* balance = nullptr) {
    const Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/structures/" + name + ".toml", overrides);
    auto b = test::build_dem(s);
    const long long every = std::max(1LL, std::llround(s.run.output_interval / b->time_step()));
    std::vector<Sample> samples;
    long long k = 0;
    completed = test::run_dem(*b, s.run.duration, [&](const Sample& x) {
        if (k++ % every == 0) samples.push_back(x);
    });
    REQUIRE(samples.size() > 3);
    if (balance) *balance = max_balance_error(s, samples);
    return cases::analyse_case(s, samples, {true});
}

void check_metrics(const cases::CaseAnalysis& r) {
    for (const auto& m : r.metrics) {
        INFO(m.name << ": " << m.value << " against " << m.reference << " (" << m.basis << ")");
        CHECK(m.pass());
    }
}

}  // namespace

TEST_CASE("a column of three drums overturns as one body at a/g = B/H plus the ramp's lag", "[dem][structures][pushover]") {
    bool completed = false;
    double balance = 1.0;
    const auto r = pushover("column_pushover", completed, {}, &balance);
    CHECK(completed);
    INFO("max balance error " << balance << " of the motion energy");
    CHECK(balance < kClosure);   // measured 2.3e-5, through the overturning
    REQUIRE(!r.metrics.empty());
    // measured on the paper's node-to-face contact (0.1 m grid, 5 x 5 points a face): 0.2670
    // against 0.2706 (B/H = 0.2667 plus the ramp's 1.5 % lag): −1.3 %. The grid's edge row takes
    // the whole weight at B/2 once the joint opens, so the column behaves almost rigidly; the same
    // joint integrated exactly would lean and peak at 0.232 (Winkler, kn = 1e9), reported beside
    check_metrics(r);
}

// The scene's joints are the paper's node-to-face grid, whose edge row carries an opened joint at
// the very edge (as for the column above), so the wall tips near the rigid t/H: measured 0.2519
// against 0.2531 (t/H = 0.25 plus the ramp's lag), −0.5 % (0.251903 against 0.253067, session 38).
// The same joints integrated exactly lean and tip at the Winkler toe's peak (the next test)
TEST_CASE("a running-bond wall tips out of plane at a/g = t/H plus the ramp's lag", "[dem][structures][pushover]") {
    bool completed = false;
    double balance = 1.0;
    const auto r = pushover("wall_pushover", completed, {}, &balance);
    CHECK(completed);
    check_metrics(r);
    INFO("max balance error " << balance << " of the motion energy");
    CHECK(balance < kClosure);   // measured 2.4e-5, through the tipping and the bricks' fall
}

TEST_CASE("overlap scheme: a wall on penalty joints tips at the Winkler toe's peak, t/H - 3 theta*", "[dem][structures][pushover]") {
    // A wall of weight W, thickness t, height H and length L on a no-tension Winkler joint kn
    // (N/m³), turned by θ about its toe with a contact strip c wide: W = ½kn·θ·c²·L, so
    // c = A/√θ with A = √(2W/(kn·L)); the triangular pressure acts c/3 from the toe and the
    // centre of mass has moved θH/2 towards it, so the multiplier that holds it is
    // λ(θ) = t/H − θ − 2c/(3H). Its peak, where the slow ramp tips it, is at θ* = (A/(3H))^(2/3):
    // λ* = t/H − 3θ*. The error against the rigid t/H falls as kn^(−1/3). The bed joints above
    // carry less of the moment relative to their capacity (they need 0.333 and more) and stay
    // nearly closed: left out (compare/analytic's path over every joint gives 0.2159, 0.2%
    // lower). The exact overlap integral is this Winkler joint; the paper's grid
    // puts the edge row's spring at the very edge and tips near t/H (the test above).
    bool completed = false;
    double balance = 1.0;
    const auto r = pushover("wall_pushover", completed, {{"contact.scheme", "\"overlap\""}}, &balance);
    CHECK(completed);
    INFO("max balance error " << balance << " of the motion energy");
    CHECK(balance < kClosure);   // measured 7.3e-4: the bricks' fall after tipping (docs/dem.md, Energy)
    REQUIRE(!r.metrics.empty());
    const double t = 0.2, h = 0.8, l = 1.6, kn = 1e9, g = 9.81;
    const double w = 2600.0 * t * h * l * g;   // every course fills the 1.6 m (half-brick closers)
    const double a = std::sqrt(2.0 * w / (kn * l)), theta = std::pow(a / (3.0 * h), 2.0 / 3.0);
    const double peak = t / h - 3.0 * theta;   // 0.2163
    const double measured = r.metrics.front().value;
    INFO("a/g at 0.05 rad " << measured << ", Winkler toe peak " << peak << ", t/H " << t / h);
    // the measured a/g includes the ramp's lag past the peak (the rigid wall's is 1.3 %): 2 %
    CHECK(measured == Approx(peak).epsilon(0.02));
    // and the pushover kind judges it on that joint: the stack's Winkler path over every bed joint
    // under the scene's ramp, peak plus lag (measured 0.2188 against 0.2191, −0.15 %)
    check_metrics(r);
}

namespace {

// a/g at which a block of the shipped column, overlap scheme, pushed along the base's diagonal
// turns past the pushover threshold, and whether every drum turned about a horizontal axis then
double diagonal_push(int subdivision, bool& about_horizontal) {
    const std::vector<Override> set = {{"contact.scheme", "\"overlap\""},
                                       {"contact.subdivision", std::to_string(subdivision)},
                                       {"ground_motion.direction", "[0.7071067811865476, 0.7071067811865476, 0.0]"},
                                       {"ground_motion.acceleration", "[0.0, 0.26, 0.36]"},
                                       {"run.duration", "30.0"}};
    const Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/structures/column_pushover.toml", set);
    auto b = test::build_dem(s);
    double when = -1.0;
    about_horizontal = true;
    test::run_dem(*b, s.run.duration, [&](const Sample& x) {
        if (when >= 0.0) return;
        for (const auto& blk : x.blocks) {
            const Eigen::AngleAxisd r(blk.orientation);
            if (r.angle() < 0.05) continue;
            when = x.t;
            about_horizontal = about_horizontal && std::abs(r.axis().z()) < 0.05;
        }
    });
    REQUIRE(when > 2.0);
    return 0.26 + 0.10 * (when - 2.0) / 40.0;   // the record: 0.26 g at 2 s, then 0.0025 g/s
}

}  // namespace

TEST_CASE("overlap scheme: a column pushed along its base's diagonal tips about its corner at any subdivision",
          "[dem][structures][pushover]") {
    // rigid joints: λ = √2·B/H = 0.3771 (the corner lies B/√2 from the axis). Bed joints of kn
    // carry a leaning column on a triangle at the corner, h = (3W/(kn·θ))^(1/3) deep, whose
    // resultant lies h/2 inside it: λ(θ) = (B/√2 − h/2 − H_c·θ)/H_c peaks below the rigid λ
    const double weight = 2600.0 * 0.4 * 0.4 * 1.5 * 9.81, kn = 1e9, hc = 0.75, a = 0.4 / std::sqrt(2.0);
    double peak = 0.0;
    for (double theta = 1e-4; theta < 0.1; theta += 1e-5)
        peak = std::max(peak, (a - 0.5 * std::cbrt(3.0 * weight / (kn * theta)) - hc * theta) / hc);
    REQUIRE(peak == Approx(0.2924).epsilon(1e-3));   // by hand: θ = 0.02119, h = 6·H_c·θ = 0.0954 m
    bool horizontal_1 = false, horizontal_4 = false;
    const double at_1 = diagonal_push(1, horizontal_1), at_4 = diagonal_push(4, horizontal_4);
    CAPTURE(at_1, at_4, peak);
    // no twist about the vertical: before the sub-contacts' torsion springs a corner pressed on one
    // sub-cell let the drums spin, at a/g 0.308 (n = 1) and 0.337 (n = 4) at kn = 1e11
    CHECK(horizontal_1);
    CHECK(horizontal_4);
    // the sub-division does not change the answer: 0.5 %
    CHECK(at_1 == Approx(at_4).epsilon(0.005));
    // above the quasi-static peak by the ramp's lag (0.0077 for the rigid monolith, compare/analytic)
    CHECK(at_4 > peak);
    CHECK(at_4 < peak + 0.015);
}
