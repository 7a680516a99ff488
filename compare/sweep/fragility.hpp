#pragma once
/// Fragility curves: the lognormal model P(fail | x) = Φ((ln x − ln θ)/β) of the probability that
/// a block overturns at intensity x, fitted by maximum likelihood to the outcomes of single runs
/// (the binomial likelihood of every run's 0/1 outcome; docs/sweeps.md).

#include <string>
#include <vector>

namespace cairn::sweep {

/// One run's outcome at one intensity.
struct FragilityPoint {
    double intensity = 0.0;   ///< x > 0, in the unit of the plan's intensity measure (g of PGA)
    bool failed = false;      ///< the block overturned
};

/// The fitted curve.
struct FragilityFit {
    /// "fitted"; "separated" when every survivor lies below every failure (no finite maximum:
    /// β → 0, θ is then the geometric mean of the highest survivor and the lowest failure);
    /// "none" when every run failed or none did (or there are no runs)
    std::string status = "none";
    double theta = 0.0;      ///< median capacity θ, intensity unit (NaN when status is "none")
    double beta = 0.0;       ///< lognormal standard deviation β (0 when separated, NaN when "none")
    double se_ln_theta = 0.0;   ///< standard error of ln θ from the inverse Fisher information
    double se_beta = 0.0;       ///< standard error of β (delta method)
    double log_likelihood = 0.0;   ///< at the maximum
    int runs = 0;            ///< points used
    int failures = 0;        ///< of which failed
    int iterations = 0;      ///< Fisher-scoring iterations taken
};

/// standard normal distribution function Φ
double normal_cdf(double x);

/// the lognormal fragility at x: Φ((ln x − ln θ)/β); a step at θ when β = 0
double fragility_at(const FragilityFit& fit, double x);

/// maximum-likelihood fit of θ and β to `points` (probit regression of the outcome on ln x, by
/// Fisher scoring); throws cairn::Error for a non-positive or non-finite intensity
FragilityFit fit_lognormal_fragility(const std::vector<FragilityPoint>& points);

}  // namespace cairn::sweep
