// the structure oracles: an arch's minimum thickness, a stack's overturning multipliers
#include <catch2/catch.hpp>

#include <cmath>

#include "analytic/arch_lateral.hpp"
#include "analytic/arch_thrust.hpp"
#include "analytic/stack_pushover.hpp"

using namespace cairn::oracle;

TEST_CASE("the minimum thickness of a semicircular arch tends to Milankovitch's 0.1075 as joints multiply", "[oracle][arch]") {
    // the published value has 4 digits: half a unit of the last is 0.05 %; N = 201 is within
    // 3e-5 of the limit (the N = 101 → 201 change is 1.3e-5)
    CHECK(SemicircularArch{201}.minimum_thickness() == Approx(kMilankovitchMinimum).epsilon(5e-4));
    // fewer joints constrain the thrust line less: odd N (a keystone at the crown) approach from
    // below (measured 0.0966, 0.1021, 0.1063, 0.1070, 0.1072 for N = 5, 9, 15, 25, 31)
    double prev = 0.0;
    for (int n : {5, 9, 15, 25, 31, 51, 101}) {
        const double t = SemicircularArch{n}.minimum_thickness();
        INFO("N = " << n << ": t/R = " << t);
        CHECK(t > prev);
        CHECK(t < kMilankovitchMinimum);
        prev = t;
    }
    // the 25-voussoir arch of scenarios/structures: 0.10703
    CHECK(SemicircularArch{25}.minimum_thickness() == Approx(0.10703).margin(1e-5));
}

TEST_CASE("a thrust line fits above the minimum thickness and not below it", "[oracle][arch]") {
    const SemicircularArch arch{25};
    const double t = arch.minimum_thickness();
    CHECK(arch.thrust_line_fits(1.001 * t));
    CHECK_FALSE(arch.thrust_line_fits(0.999 * t));
    CHECK(arch.thrust_line_fits(0.22));   // the 9-voussoir arch's t/R of the shipped arch scene
    // three voussoirs have only four joints: no symmetric 5-hinge mechanism, any thickness stands
    CHECK(SemicircularArch{3}.thrust_line_fits(0.01));
}

TEST_CASE("a stack overturns about its base at B/H, above which sub-stacks need more", "[oracle][pushover]") {
    const double m = 0.4 * 0.4 * 0.5 * 2600.0;
    const BlockStack column{{{0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}}, 9.81};
    CHECK(column.rigid_multiplier() == Approx(0.4 / 1.5).epsilon(1e-12));
    // the top drum alone needs B/h = 0.8, the top two 0.4: a short base mechanism would win
    const BlockStack narrow_top{{{0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}, {0.5, 0.1, 0.4, m / 4}}, 9.81};
    CHECK(narrow_top.rigid_multiplier() == Approx(std::min(0.1 / 0.5, 0.2 / 0.55)).epsilon(1e-12));
    // Winkler joints: the peak falls below B/H by ~ kn^(-1/3) and tends to it as kn grows
    // (measured 0.2321 at 1e9, 0.2507 at 1e10, 0.2592 at 1e11)
    double prev = 0.0;
    for (double kn : {1e9, 1e10, 1e11, 1e13}) {
        const double w = column.winkler_multiplier(kn);
        INFO("kn = " << kn << ": " << w);
        CHECK(w > prev);
        CHECK(w < column.rigid_multiplier());
        prev = w;
    }
    CHECK(column.winkler_multiplier(1e13) == Approx(column.rigid_multiplier()).epsilon(0.01));
    // one joint: the closed form of the peak of N(B/2 − a/3) − N h θ, a = √(2N/(kn D θ)):
    // θ* = (√(2N/(kn D))/(6h))^(2/3)
    const BlockStack mono{{{1.5, 0.4, 0.4, 3 * m}}, 9.81};
    const double n = 3 * m * 9.81, h = 0.75, k = std::sqrt(2 * n / (1e9 * 0.4));
    const double th = std::pow(k / (6 * h), 2.0 / 3.0);
    CHECK(mono.winkler_multiplier(1e9) == Approx((0.2 - k / (3 * std::sqrt(th)) - h * th) / h).epsilon(1e-4));
}

TEST_CASE("a rigid stack under a ramp tips when λ passes B/H plus the ramp's lag", "[oracle][pushover]") {
    const double m = 0.4 * 0.4 * 0.5 * 2600.0;
    const BlockStack column{{{0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}}, 9.81};
    auto ramp = [](double rate) { return [rate](double t) { return t < 2 ? 0.1 * t : 0.2 + rate * (t - 2); }; };
    double prev_lag = INFINITY;
    for (double rate : {1e-2, 5e-3, 2.5e-3, 1e-3}) {
        const double t = column.rigid_ramp_time(ramp(rate), 0.05, 500.0);
        const double lag = ramp(rate)(t) - column.rigid_multiplier();
        INFO("rate " << rate << ": lag " << lag);
        CHECK(lag > 0.0);         // nothing tips before λ reaches B/H
        CHECK(lag < prev_lag);    // slower ramps come closer (measured +1.5 % at 2.5e-3 g/s)
        prev_lag = lag;
    }
    CHECK(std::isnan(column.rigid_ramp_time([](double) { return 0.25; }, 0.05, 10.0)));   // below B/H: never
}

TEST_CASE("the rigid stack turns about its edge as work and energy say, under a constant push", "[oracle][pushover]") {
    // three 0.4 × 0.4 × 0.5 m drums as one 0.4 × 1.5 m column (b = 0.2, h = 0.75 m about its edge,
    // i = (4/3)m(b² + h²)) under λ = 0.3 held from t = 0: the push's work and the weight's rise give
    // ½iω² = m g[λ(h sin θ + b(1 − cos θ)) − (b sin θ + h(cos θ − 1))], so the time to 0.05 rad is
    // ∫dθ/ω (Simpson in u = √θ, where the integrand stays finite). The height of the centre above
    // the edge is h cos θ + b sin θ: with − b sin θ, the lever of a sign slip, it came 1.3 % late
    const double m = 0.4 * 0.4 * 0.5 * 2600.0, g = 9.81, b = 0.2, h = 0.75, lambda = 0.3, to = 0.05;
    const BlockStack column{{{0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}}, g};
    const double i_m = 4.0 / 3.0 * (b * b + h * h);
    auto integrand = [&](double u) {
        if (u == 0.0) return 2.0 / std::sqrt(2.0 * g * (lambda * h - b) / i_m);   // ω ≈ √(2g(λh − b)θ/(i/m))
        const double th = u * u;
        const double work = g * (lambda * (h * std::sin(th) + b * (1 - std::cos(th))) - (b * std::sin(th) + h * (std::cos(th) - 1)));
        return 2.0 * u / std::sqrt(2.0 * work / i_m);
    };
    const int n = 20000;
    const double top = std::sqrt(to);
    double sum = integrand(0.0) + integrand(top);
    for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * integrand(k * top / n);
    const double expected = sum * top / n / 3.0;   // 0.514388 s
    // 2e-4 s: the integration's 1e-4 s step, at whose end the threshold is read
    CHECK(column.rigid_ramp_time([&](double) { return lambda; }, to, 10.0) == Approx(expected).margin(2e-4));
}

TEST_CASE("a stack narrower above turns about its critical joint, rigid or on Winkler joints", "[oracle][pushover]") {
    // two 0.5 × 0.5 × 0.4 m blocks under two 0.3 × 0.3 × 0.4 m ones: the upper two turn about the
    // narrower joint at λ = 0.15/0.4 = 0.375, the whole stack about the base only at 0.408
    const double big = 0.5 * 0.5 * 0.4 * 2600.0, small = 0.3 * 0.3 * 0.4 * 2600.0;
    const BlockStack taper{{{0.4, 0.5, 0.5, big}, {0.4, 0.5, 0.5, big}, {0.4, 0.3, 0.3, small}, {0.4, 0.3, 0.3, small}},
                           9.81};
    CHECK(taper.rigid_multiplier() == Approx(0.375).epsilon(1e-12));
    auto ramp = [](double t) { return t < 2 ? 0.15 * t : 0.3 + 2.5e-3 * (t - 2); };
    // the sub-stack's lag, not the monolith's: measured 0.3783 (Bullet 0.3779, Siconos 0.3781);
    // about the base it would be past 0.408
    const double rigid = ramp(taper.rigid_ramp_time(ramp, 0.05, 100.0));
    CHECK(rigid > 0.375);
    CHECK(rigid < 0.385);
    // the Winkler path runs in the top's rotation, which the upper joint turns while the base's
    // stays put (a path in the base joint's rotation was lost there): its peak, then the lag
    const double peak = taper.winkler_multiplier(1e10);
    REQUIRE(std::isfinite(peak));
    CHECK(peak < 0.375);
    const double winkler = ramp(taper.winkler_ramp_time(1e10, ramp, 0.05, 100.0));
    CHECK(winkler > peak);
    CHECK(winkler < rigid);   // measured 0.3601; dem 0.3594
}

TEST_CASE("a stack on Winkler joints under a ramp tips past its peak, and as the rigid stack as kn grows",
          "[oracle][pushover]") {
    const double m = 0.4 * 0.4 * 0.5 * 2600.0;
    const BlockStack column{{{0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}}, 9.81};
    auto ramp = [](double rate) { return [rate](double t) { return t < 2 ? 0.1 * t : 0.2 + rate * (t - 2); }; };
    const double rigid = ramp(2.5e-3)(column.rigid_ramp_time(ramp(2.5e-3), 0.05, 500.0));
    double prev = 0.0;
    for (double kn : {1e8, 1e9, 1e10, 1e11}) {
        const double t = column.winkler_ramp_time(kn, ramp(2.5e-3), 0.05, 500.0);
        REQUIRE(std::isfinite(t));
        const double lambda = ramp(2.5e-3)(t), peak = column.winkler_multiplier(kn);
        INFO("kn " << kn << ": a/g " << lambda << ", peak " << peak << ", rigid " << rigid);
        CHECK(lambda > peak);   // nothing runs away before the peak
        // the lag past the peak is the ramp's: the softer the joints, the flatter the path past
        // its peak and the longer the lag (measured 5.3, 1.7, 1.7, 1.6 % of the peak at kn 1e8 …
        // 1e11; the rigid stack's is 1.5 %); dem follows it to 0.25 % (docs/validation.md)
        CHECK(lambda > prev);   // stiffer joints lean less
        CHECK(lambda < rigid);
        prev = lambda;
    }
    // → the rigid stack: at kn 1e13 the joints open by micrometres (the peak is within 1 %)
    CHECK(ramp(2.5e-3)(column.winkler_ramp_time(1e13, ramp(2.5e-3), 0.05, 500.0)) == Approx(rigid).epsilon(0.01));
    // a slower ramp comes closer to the peak
    const double peak = column.winkler_multiplier(1e9);
    const double fast = ramp(5e-3)(column.winkler_ramp_time(1e9, ramp(5e-3), 0.05, 500.0)) - peak;
    const double slow = ramp(1e-3)(column.winkler_ramp_time(1e9, ramp(1e-3), 0.05, 500.0)) - peak;
    CHECK(slow > 0.0);
    CHECK(slow < fast);
    // held below the peak it leans on its joints and never reaches the threshold
    CHECK(std::isnan(column.winkler_ramp_time(1e9, [&](double) { return 0.98 * peak; }, 0.05, 10.0)));
    // a record that starts from a multiplier starts from the stack's static lean under it: a
    // constant 0.9 of the peak leaves it there: started upright it would swing to about twice
    // that lean, past the peak's rotation, and run away
    const double held = column.winkler_ramp_time(1e9, [&](double) { return 0.9 * peak; },
                                                 column.winkler_peak_rotation(1e9), 5.0);
    CHECK(std::isnan(held));
}

TEST_CASE("an arch under a lateral acceleration: the thrust line of its weight at 0, none past the collapse", "[oracle][arch]") {
    // λ = 0 is the symmetric problem of SemicircularArch, solved here as an asymmetric one: the
    // same least thickness, within the bisections' resolution
    for (int n : {9, 21, 25}) {
        const double least = SemicircularArch{n}.minimum_thickness();
        INFO("N = " << n);
        CHECK(ArchUnderLateralLoad{n, 1.001 * least}.thrust_line_fits(0.0));
        CHECK_FALSE(ArchUnderLateralLoad{n, 0.999 * least}.thrust_line_fits(0.0));
        CHECK(ArchUnderLateralLoad{n, 0.999 * least}.collapse_acceleration() == 0.0);
        // just above the least thickness the arch takes almost no lateral load
        CHECK(ArchUnderLateralLoad{n, 1.01 * least}.collapse_acceleration() < 0.01);
    }
    // thicker arches take more, and the 21-voussoir arch at t/R = 0.15 takes 0.1479 g: four
    // rigid engines keep it up at 0.95 times that and let it fall at 1.05 times
    // (test_engine_arch_lateral.cpp)
    double prev = 0.0;
    for (double t : {0.12, 0.15, 0.2, 0.3}) {
        const double lambda = ArchUnderLateralLoad{21, t}.collapse_acceleration();
        INFO("t/R = " << t << ": λ = " << lambda);
        CHECK(lambda > prev);
        prev = lambda;
    }
    const ArchUnderLateralLoad arch{21, 0.15};
    const double lambda = arch.collapse_acceleration();
    CHECK(arch.thrust_line_fits(0.999 * lambda));
    CHECK_FALSE(arch.thrust_line_fits(1.001 * lambda));
    // the value the four engines were checked against (the same statics in a Python script: 0.14786)
    CHECK(lambda == Approx(0.14786).margin(2e-4));
}

TEST_CASE("a stack pushed at an angle to its layers' axes overturns over a corner", "[oracle][pushover]") {
    const double m = 0.4 * 0.4 * 0.5 * 2600.0;
    BlockStack column{{{0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}}, 9.81};
    // a hair off the width axis: the two-direction path gives the one-direction one (to the
    // continuation's own tolerance, 1e-13 in the unknowns)
    const double along = column.winkler_multiplier(1e10);
    column.push_angle = 1e-6;
    CHECK(column.winkler_multiplier(1e10) == Approx(along).epsilon(1e-6));
    CHECK(column.rigid_multiplier() == Approx(0.4 / 1.5).epsilon(1e-5));
    // at 45° to a square section the resultant leaves over a corner: √2·B/H
    column.push_angle = std::atan(1.0);
    CHECK(column.rigid_multiplier() == Approx(std::sqrt(2.0) * 0.4 / 1.5).epsilon(1e-12));
    double prev = 0.0;
    for (double kn : {1e9, 1e11, 1e13}) {
        const double w = column.winkler_multiplier(kn);
        INFO("45 degrees, kn = " << kn << ": " << w << " against " << column.rigid_multiplier());
        CHECK(w > prev);
        CHECK(w < column.rigid_multiplier());
        prev = w;
    }
    // how the peak approaches the rigid value: λ(θ) = λr − c·(N/(kn·θ))^p/h − θ near the edge the
    // stack turns about, its contact an area of size (N/(kn·θ))^p: a strip along a side (p = 1/2)
    // or a triangle at a corner (p = 1/3). The peak's deficit falls as kn^(−p/(1+p)): kn^(−1/3)
    // along an axis, kn^(−1/4) over a corner. Over two decades of kn the ratios are 100^(1/3) =
    // 4.64 and 100^(1/4) = 3.16 (3 %: the next terms, measured 4.63 and 3.16; beyond kn 1e13 the
    // continuation loses 0.4 m drums to round-off in one build or another and gives NaN)
    const double corner = column.rigid_multiplier();
    const double corner_ratio =
        (corner - column.winkler_multiplier(1e11)) / (corner - column.winkler_multiplier(1e13));
    CHECK(corner_ratio == Approx(std::pow(100.0, 0.25)).epsilon(0.03));
    column.push_angle = 0.0;
    const double edge = column.rigid_multiplier();
    const double edge_ratio = (edge - column.winkler_multiplier(1e11)) / (edge - column.winkler_multiplier(1e13));
    CHECK(edge_ratio == Approx(std::pow(100.0, 1.0 / 3.0)).epsilon(0.03));
    // a 1.2 m long, 0.2 m thick wall given along its length and pushed at 90°, across it: t/H
    const BlockStack wall{{{1.0, 0.2, 1.2, 624.0}}, 9.81};
    const BlockStack turned{{{1.0, 1.2, 0.2, 624.0}}, 9.81, 2 * std::atan(1.0)};
    CHECK(turned.rigid_multiplier() == Approx(0.2 / 1.0).epsilon(1e-12));
    CHECK(turned.winkler_multiplier(1e9) == Approx(wall.winkler_multiplier(1e9)).epsilon(1e-12));
}
