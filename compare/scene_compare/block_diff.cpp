#include "scene_compare/block_diff.hpp"

#include <algorithm>

#include "metrics/signal.hpp"

namespace cairn::scene_compare {

BlockDiff block_diff(const BlockHistory& run, const BlockHistory& base, const DivergenceThresholds& th) {
    BlockDiff d;
    if (run.t.empty() || base.t.size() < 2) return d;
    const metrics::Series bx{base.t, base.x}, by{base.t, base.y}, bz{base.t, base.z};
    const metrics::Series ba{base.t, base.angle}, bs{base.t, base.speed};
    const double end = base.t.back() + 1e-12;
    double sp = 0.0, sa = 0.0, ss = 0.0;
    size_t n = 0;
    d.position_peak = 0.0;
    d.angle_peak = 0.0;
    for (size_t i = 0; i < run.t.size(); ++i) {
        const double t = run.t[i];
        if (t < base.t.front() - 1e-12 || t > end) continue;
        const double dx = run.x[i] - metrics::interpolate(bx, t), dy = run.y[i] - metrics::interpolate(by, t),
                     dz = run.z[i] - metrics::interpolate(bz, t);
        const double dp = std::sqrt(dx * dx + dy * dy + dz * dz);
        const double da = std::abs(run.angle[i] - metrics::interpolate(ba, t));
        const double ds = run.speed[i] - metrics::interpolate(bs, t);
        sp += dp * dp;
        sa += da * da;
        ss += ds * ds;
        ++n;
        d.position_peak = std::max(d.position_peak, dp);
        d.angle_peak = std::max(d.angle_peak, da);
        if (std::isnan(d.position_diverged) && dp > th.position) d.position_diverged = t;
        if (std::isnan(d.angle_diverged) && da > th.angle) d.angle_diverged = t;
        d.compared_until = t;
    }
    if (n == 0) return BlockDiff{};
    d.position_rms = std::sqrt(sp / double(n));
    d.angle_rms = std::sqrt(sa / double(n));
    d.speed_rms = std::sqrt(ss / double(n));
    return d;
}

BlockPeaks block_peaks(const BlockHistory& h) {
    BlockPeaks p;
    for (size_t i = 0; i < h.t.size(); ++i) {
        const double dx = h.x[i] - h.x[0], dy = h.y[i] - h.y[0], dz = h.z[i] - h.z[0];
        p.displacement = std::max(p.displacement, std::sqrt(dx * dx + dy * dy + dz * dz));
        p.angle = std::max(p.angle, h.angle[i]);
        p.speed = std::max(p.speed, h.speed[i]);
    }
    return p;
}

}  // namespace cairn::scene_compare
