#include "analytic/housner_calibration.hpp"

#include <algorithm>
#include <cmath>

#include "analytic/oracles.hpp"

namespace cairn::oracle {

HousnerDamping calibrate_housner_damping(SpringBlock block, double theta0, int impacts, double duration, double zeta_max) {
    const HousnerBlock hb{0.5 * block.width, 0.5 * block.height, block.g};
    HousnerDamping best;
    for (int k = 1; k <= impacts; ++k) best.housner.push_back(hb.amplitude_after(theta0, k));
    // the largest relative miss of the first `impacts` amplitudes at ζ (a swing missing counts as 100 %)
    auto score = [&](double zeta, std::vector<double>* amps) {
        block.zeta = zeta;
        const auto tr = block.rock(theta0, duration, duration);
        double worst = 0.0;
        for (int k = 0; k < impacts; ++k) {
            const double a = size_t(k) < tr.amplitudes.size() ? tr.amplitudes[size_t(k)] : 0.0;
            worst = std::max(worst, std::abs(a / best.housner[size_t(k)] - 1.0));
        }
        if (amps) *amps = tr.amplitudes;
        return worst;
    };
    const int n = 100;
    double z_best = 0.0, s_best = 1e300;
    for (int i = 0; i <= n; ++i) {
        const double z = zeta_max * i / n, s = score(z, nullptr);
        if (s < s_best) s_best = s, z_best = z;
    }
    // golden section on the bracket around the best scan point
    double lo = std::max(0.0, z_best - zeta_max / n), hi = std::min(zeta_max, z_best + zeta_max / n);
    const double r = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = hi - r * (hi - lo), b = lo + r * (hi - lo), fa = score(a, nullptr), fb = score(b, nullptr);
    for (int i = 0; i < 40; ++i) {
        if (fa < fb) hi = b, b = a, fb = fa, a = hi - r * (hi - lo), fa = score(a, nullptr);
        else lo = a, a = b, fa = fb, b = lo + r * (hi - lo), fb = score(b, nullptr);
    }
    const double z = fa < fb ? a : b;
    if (std::min(fa, fb) < s_best) z_best = z;
    best.zeta = z_best;
    best.worst = score(z_best, &best.amplitudes);
    best.amplitudes.resize(std::min(best.amplitudes.size(), size_t(impacts)));
    return best;
}

}  // namespace cairn::oracle
