#include "sweep/fragility.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "error.hpp"

namespace cairn::sweep {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// standard normal density
double normal_pdf(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * M_PI); }

/// log-likelihood of the probit model p = Φ(a + b z) for the points (z = ln x)
double log_likelihood(const std::vector<double>& z, const std::vector<int>& y, double a, double b) {
    double l = 0.0;
    for (size_t i = 0; i < z.size(); ++i) {
        const double eta = a + b * z[i];
        // ln Φ(±η) through erfc keeps the tails accurate
        const double p = y[i] ? normal_cdf(eta) : normal_cdf(-eta);
        l += std::log(std::max(p, 1e-300));
    }
    return l;
}

}  // namespace

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double fragility_at(const FragilityFit& fit, double x) {
    if (fit.status == "none" || !(x > 0.0)) return kNaN;
    if (fit.beta <= 0.0) return x < fit.theta ? 0.0 : 1.0;
    return normal_cdf((std::log(x) - std::log(fit.theta)) / fit.beta);
}

FragilityFit fit_lognormal_fragility(const std::vector<FragilityPoint>& points) {
    FragilityFit fit;
    std::vector<double> z;
    std::vector<int> y;
    double hi_survivor = -std::numeric_limits<double>::infinity();
    double lo_failure = std::numeric_limits<double>::infinity();
    for (const auto& p : points) {
        if (!std::isfinite(p.intensity) || p.intensity <= 0.0)
            throw Error("fragility fit: intensity " + message_number(p.intensity) + " is not a positive number");
        z.push_back(std::log(p.intensity));
        y.push_back(p.failed ? 1 : 0);
        fit.failures += p.failed ? 1 : 0;
        if (p.failed) lo_failure = std::min(lo_failure, p.intensity);
        else hi_survivor = std::max(hi_survivor, p.intensity);
    }
    fit.runs = int(points.size());
    fit.theta = fit.beta = fit.se_ln_theta = fit.se_beta = fit.log_likelihood = kNaN;
    if (fit.failures == 0 || fit.failures == fit.runs) return fit;
    if (hi_survivor < lo_failure) {
        // complete separation: the likelihood grows without bound as β → 0
        fit.status = "separated";
        fit.theta = std::sqrt(hi_survivor * lo_failure);
        fit.beta = 0.0;
        fit.log_likelihood = 0.0;
        return fit;
    }

    // start: θ at the mean of ln x, β at their standard deviation (at least 0.1)
    double mean = 0.0, var = 0.0;
    for (double v : z) mean += v;
    mean /= double(z.size());
    for (double v : z) var += (v - mean) * (v - mean);
    const double sd = std::max(std::sqrt(var / double(z.size())), 0.1);
    double a = -mean / sd, b = 1.0 / sd;
    double l = log_likelihood(z, y, a, b);
    double i00 = 0, i01 = 0, i11 = 0;   // Fisher information of (a, b)
    for (int it = 1; it <= 200; ++it) {
        double u0 = 0, u1 = 0;
        i00 = i01 = i11 = 0;
        for (size_t i = 0; i < z.size(); ++i) {
            const double eta = a + b * z[i];
            const double p = std::clamp(normal_cdf(eta), 1e-300, 1.0 - 1e-16);
            const double q = std::clamp(normal_cdf(-eta), 1e-300, 1.0);
            const double f = normal_pdf(eta);
            const double g = (y[i] ? f / p : -f / q);   // d ln L_i / d eta
            const double w = f * f / (p * q);           // expected information per unit eta
            u0 += g;
            u1 += g * z[i];
            i00 += w;
            i01 += w * z[i];
            i11 += w * z[i] * z[i];
        }
        const double det = i00 * i11 - i01 * i01;
        if (!(det > 0.0)) break;
        double da = (i11 * u0 - i01 * u1) / det, db = (i00 * u1 - i01 * u0) / det;
        // step halving keeps the likelihood rising and b positive
        double step = 1.0, l_new = l;
        for (int h = 0; h < 40; ++h, step *= 0.5) {
            if (b + step * db <= 0.0) continue;
            l_new = log_likelihood(z, y, a + step * da, b + step * db);
            if (l_new >= l - 1e-12) break;
        }
        a += step * da;
        b += step * db;
        const bool converged = std::abs(step * da) < 1e-12 * (1.0 + std::abs(a)) &&
                               std::abs(step * db) < 1e-12 * (1.0 + std::abs(b));
        l = l_new;
        fit.iterations = it;
        if (converged) break;
    }
    fit.status = "fitted";
    fit.theta = std::exp(-a / b);
    fit.beta = 1.0 / b;
    fit.log_likelihood = l;
    // covariance of (a, b) = I⁻¹; ln θ = −a/b and β = 1/b by the delta method
    const double det = i00 * i11 - i01 * i01;
    if (det > 0.0) {
        const double c00 = i11 / det, c01 = -i01 / det, c11 = i00 / det;
        const double ga = -1.0 / b, gb = a / (b * b);
        fit.se_ln_theta = std::sqrt(ga * ga * c00 + 2 * ga * gb * c01 + gb * gb * c11);
        fit.se_beta = std::sqrt(c11) / (b * b);
    }
    return fit;
}

}  // namespace cairn::sweep
