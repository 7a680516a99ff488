#include "analytic/winkler_block.hpp"

#include <algorithm>
#include <cmath>

namespace cairn::oracle {

double WinklerBlock::eccentricity(double load, double height) const {
    const double e0 = load * height / weight, a = std::abs(e0);
    if (com_height <= 0.0 || a == 0.0) return e0;
    // f(e) = e − |e0| − h_c·θ(e) is negative at |e0| and falls to −∞ at B/2: scan for its first
    // rise through 0, then bisect
    auto f = [&](double e) { return e - a - com_height * tilt(e); };
    const int n = 2000;
    double lo = a, hi = NAN;
    for (int i = 1; i < n; ++i) {
        const double e = a + (0.5 * width - a) * double(i) / n;
        if (f(e) >= 0.0) { hi = e; break; }
        lo = e;
    }
    if (std::isnan(hi)) return NAN;
    for (int i = 0; i < 100 && hi - lo > 1e-15 * width; ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) < 0.0 ? lo : hi) = mid;
    }
    return std::copysign(0.5 * (lo + hi), e0);
}

double WinklerBlock::tilt(double e) const {
    e = std::abs(e);
    if (e <= width / 6.0) return 12.0 * weight * e / (kn * depth * width * width * width);
    const double c = contact_length(e);
    return c > 0.0 ? peak_penetration(e) / c : INFINITY;
}

double WinklerBlock::rocking_period(double e, double inertia) const {
    e = std::abs(e);
    const double springs = e <= width / 6.0 ? kn * depth * width * width * width / 12.0
                                            : weight * contact_length(e) / (6.0 * tilt(e));
    const double k = springs - weight * com_height;   // the weight's shift over the tilt softens it
    return k > 0.0 ? 2.0 * M_PI * std::sqrt(inertia / k) : INFINITY;
}

double WinklerBlock::contact_length(double e) const {
    e = std::abs(e);
    if (e <= width / 6.0) return width;
    return std::max(0.0, 3.0 * (0.5 * width - e));
}

double WinklerBlock::peak_penetration(double e) const {
    e = std::abs(e);
    if (e <= width / 6.0) return weight / (kn * width * depth) * (1.0 + 6.0 * e / width);
    const double c = contact_length(e);
    return c > 0.0 ? 2.0 * weight / (kn * depth * c) : INFINITY;
}

double WinklerBlock::penetration_at(double e, double s) const {
    e = std::abs(e);
    const double c = contact_length(e), d = peak_penetration(e);
    if (s < 0.0 || s > c) return 0.0;
    if (e <= width / 6.0) {
        // linear from the toe (1 + 6e/B) to the heel (1 − 6e/B), times W/(kn·A)
        const double mean = weight / (kn * width * depth);
        return mean * (1.0 + 6.0 * e / width * (1.0 - 2.0 * s / width));
    }
    return d * (1.0 - s / c);   // triangle: d_max at the toe, 0 at s = c
}

double WinklerBlock::base_shear(double e, double u) const {
    // midpoint rule on a fine grid: the integrand has one kink (where the slip zone ends)
    const double c = contact_length(e);
    const int n = 20000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double s = (i + 0.5) * c / n;
        sum += std::min(ks * u, mu * kn * penetration_at(e, s));
    }
    return depth * sum * c / n;
}

double WinklerBlock::shear_displacement(double load, double height) const {
    if (load >= mu * weight) return NAN;
    const double e = std::abs(eccentricity(load, height));
    if (!(e < 0.5 * width)) return NAN;   // it tips (NaN: no equilibrium with the weight's shift)
    if (e > width / 6.0) {
        // partial contact: the slip zone (μ·p < ks·u) is the lightly pressed end of the triangle
        const double d = peak_penetration(e);
        return mu * kn / ks * d * (1.0 - std::sqrt(1.0 - load / (mu * weight)));
    }
    const double elastic = load / (ks * width * depth);
    const double heel = penetration_at(e, width);   // the least pressed point
    if (ks * elastic <= mu * kn * heel) return elastic;   // every point sticks
    // some points slip: the base shear grows monotonically with u; bisect H = base_shear(u)
    double lo = elastic, hi = mu * kn / ks * peak_penetration(e);
    for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
        const double mid = 0.5 * (lo + hi);
        (base_shear(e, mid) < load ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace cairn::oracle
