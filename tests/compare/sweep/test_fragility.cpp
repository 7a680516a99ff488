// the lognormal fragility fit against samples drawn from a known lognormal curve
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "error.hpp"
#include "sweep/fragility.hpp"

using namespace cairn;
using namespace cairn::sweep;

namespace {

/// a uniform number in [0, 1) from 53 bits of a fully specified generator (same on every platform)
double uniform(std::mt19937_64& g) { return double(g() >> 11) * 0x1.0p-53; }

/// `per` runs at each intensity, each failing with probability Φ((ln x − ln θ)/β)
std::vector<FragilityPoint> draw(std::mt19937_64& g, double theta, double beta, const std::vector<double>& xs, int per) {
    std::vector<FragilityPoint> pts;
    for (double x : xs)
        for (int k = 0; k < per; ++k)
            pts.push_back({x, uniform(g) < normal_cdf((std::log(x) - std::log(theta)) / beta)});
    return pts;
}

const std::vector<double> kIntensities{0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0};   // g

}  // namespace

TEST_CASE("the lognormal fit recovers θ and β of a known curve within its standard errors", "[sweep][fragility]") {
    const double theta = 0.35, beta = 0.4;
    std::mt19937_64 g(20261123);
    const auto fit = fit_lognormal_fragility(draw(g, theta, beta, kIntensities, 40));
    REQUIRE(fit.status == "fitted");
    CHECK(fit.runs == 400);
    // 3 standard errors: a correct estimator misses by more in 0.3 % of samples (the seed is fixed)
    CHECK(std::abs(std::log(fit.theta) - std::log(theta)) < 3.0 * fit.se_ln_theta);
    CHECK(std::abs(fit.beta - beta) < 3.0 * fit.se_beta);
    // the standard errors are those of 400 runs: a few per cent of ln θ, not 0 and not 1
    CHECK(fit.se_ln_theta > 0.01);
    CHECK(fit.se_ln_theta < 0.1);
}

TEST_CASE("the fit's standard errors match the spread of the estimates over repeated samples", "[sweep][fragility]") {
    const double theta = 0.35, beta = 0.4;
    std::mt19937_64 g(7);
    const int samples = 300;
    double s_ln = 0, s2_ln = 0, s_b = 0, s2_b = 0, se_ln = 0, se_b = 0;
    for (int k = 0; k < samples; ++k) {
        const auto f = fit_lognormal_fragility(draw(g, theta, beta, kIntensities, 20));
        REQUIRE(f.status == "fitted");
        s_ln += std::log(f.theta);
        s2_ln += std::log(f.theta) * std::log(f.theta);
        s_b += f.beta;
        s2_b += f.beta * f.beta;
        se_ln += f.se_ln_theta / samples;
        se_b += f.se_beta / samples;
    }
    const double sd_ln = std::sqrt(s2_ln / samples - (s_ln / samples) * (s_ln / samples));
    const double sd_b = std::sqrt(s2_b / samples - (s_b / samples) * (s_b / samples));
    // the sample standard deviation of 300 estimates is itself uncertain by 1/sqrt(2·300) ≈ 4 %;
    // 20 % also covers the small-sample bias of the asymptotic (Fisher) standard error at 200 runs
    CHECK(sd_ln == Approx(se_ln).epsilon(0.2));
    CHECK(sd_b == Approx(se_b).epsilon(0.2));
    // the mean estimates: unbiased within 3 standard errors of the mean of 300
    CHECK(std::abs(s_ln / samples - std::log(theta)) < 3.0 * sd_ln / std::sqrt(double(samples)));
    CHECK(std::abs(s_b / samples - beta) < 0.05 * beta + 3.0 * sd_b / std::sqrt(double(samples)));
}

TEST_CASE("the fit is a maximum: the log-likelihood falls when θ or β moves", "[sweep][fragility]") {
    std::mt19937_64 g(11);
    const auto pts = draw(g, 0.5, 0.3, kIntensities, 10);
    const auto fit = fit_lognormal_fragility(pts);
    REQUIRE(fit.status == "fitted");
    auto ll = [&](double theta, double beta) {
        double l = 0;
        for (const auto& p : pts) {
            const double q = normal_cdf((std::log(p.intensity) - std::log(theta)) / beta);
            l += std::log(p.failed ? q : 1.0 - q);
        }
        return l;
    };
    CHECK(ll(fit.theta, fit.beta) == Approx(fit.log_likelihood).epsilon(1e-9));
    for (double f : {0.99, 1.01}) {
        CHECK(ll(fit.theta * f, fit.beta) < fit.log_likelihood);
        CHECK(ll(fit.theta, fit.beta * f) < fit.log_likelihood);
    }
}

TEST_CASE("separated and one-sided samples are reported, not fitted", "[sweep][fragility]") {
    // every survivor below every failure: no finite maximum, a step at the geometric mean
    const auto sep = fit_lognormal_fragility({{0.1, false}, {0.2, false}, {0.4, true}, {0.8, true}});
    CHECK(sep.status == "separated");
    CHECK(sep.theta == Approx(std::sqrt(0.2 * 0.4)));
    CHECK(sep.beta == 0.0);
    CHECK(fragility_at(sep, 0.25) == 0.0);
    CHECK(fragility_at(sep, 0.3) == 1.0);
    CHECK(fit_lognormal_fragility({{0.1, false}, {0.2, false}}).status == "none");
    CHECK(fit_lognormal_fragility({{0.1, true}}).status == "none");
    CHECK(fit_lognormal_fragility({}).status == "none");
    CHECK_THROWS_AS(fit_lognormal_fragility({{0.0, true}, {0.1, false}}), Error);
}
