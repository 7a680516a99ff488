#include "scene_compare/block_diff.hpp"

#include <algorithm>
#include <numeric>

#include "metrics/signal.hpp"
#include "output/number_format.hpp"
#include "run/run_jobs.hpp"

namespace cairn::scene_compare {

DifferenceSeries differences(const BlockHistory& run, const BlockHistory& base) {
    DifferenceSeries d;
    if (base.t.size() < 2) return d;
    const metrics::Series bx{base.t, base.x}, by{base.t, base.y}, bz{base.t, base.z};
    const metrics::Series ba{base.t, base.angle}, bs{base.t, base.speed};
    for (size_t i = 0; i < run.t.size(); ++i) {
        const double t = run.t[i];
        if (t < base.t.front() - 1e-12 || t > base.t.back() + 1e-12) continue;
        const double dx = run.x[i] - metrics::interpolate(bx, t), dy = run.y[i] - metrics::interpolate(by, t),
                     dz = run.z[i] - metrics::interpolate(bz, t);
        d.t.push_back(t);
        d.distance.push_back(std::sqrt(dx * dx + dy * dy + dz * dz));
        d.angle.push_back(run.angle[i] - metrics::interpolate(ba, t));
        d.speed.push_back(run.speed[i] - metrics::interpolate(bs, t));
    }
    return d;
}

BlockDiff block_diff(const BlockHistory& run, const BlockHistory& base, const DivergenceThresholds& th) {
    const DifferenceSeries s = differences(run, base);
    BlockDiff d;
    if (s.t.empty()) return d;
    double sp = 0.0, sa = 0.0, ss = 0.0;
    d.position_peak = 0.0;
    d.angle_peak = 0.0;
    for (size_t i = 0; i < s.t.size(); ++i) {
        const double dp = s.distance[i], da = std::abs(s.angle[i]), ds = s.speed[i];
        sp += dp * dp;
        sa += da * da;
        ss += ds * ds;
        d.position_peak = std::max(d.position_peak, dp);
        d.angle_peak = std::max(d.angle_peak, da);
        if (std::isnan(d.position_diverged) && dp > th.position) d.position_diverged = s.t[i];
        if (std::isnan(d.angle_diverged) && da > th.angle) d.angle_diverged = s.t[i];
    }
    const double n = double(s.t.size());
    d.position_rms = std::sqrt(sp / n);
    d.angle_rms = std::sqrt(sa / n);
    d.speed_rms = std::sqrt(ss / n);
    d.compared_until = s.t.back();
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

std::vector<size_t> blocks_to_show(const std::vector<std::vector<BlockPeaks>>& peaks_of, size_t blocks,
                                   int max_shown) {
    std::vector<size_t> all(blocks);
    std::iota(all.begin(), all.end(), size_t(0));
    const size_t n = size_t(std::max(0, max_shown));
    if (blocks <= n) return all;
    std::vector<BlockPeaks> most(blocks);   // per block, the largest over the variants
    for (const auto& variant : peaks_of)
        for (size_t b = 0; b < std::min(blocks, variant.size()); ++b) {
            most[b].displacement = std::max(most[b].displacement, variant[b].displacement);
            most[b].angle = std::max(most[b].angle, variant[b].angle);
        }
    std::stable_sort(all.begin(), all.end(), [&](size_t a, size_t b) {
        if (most[a].displacement != most[b].displacement) return most[a].displacement > most[b].displacement;
        return most[a].angle > most[b].angle;
    });
    all.resize(n);
    std::sort(all.begin(), all.end());
    return all;
}

std::string compliance_disagreement(const std::vector<VariantPeak>& peaks) {
    std::vector<double> rigid;
    for (const auto& p : peaks)
        if (p.rigid) rigid.push_back(p.angle);
    if (rigid.empty()) return {};
    const double middle = median(rigid);
    std::string far;
    for (const auto& p : peaks)
        if (p.compliant && std::abs(p.angle - middle) > std::max(0.05, 0.5 * middle))
            far += (far.empty() ? "" : ", ") + p.name + " " + number_text(p.angle, 3) + " rad";
    if (far.empty()) return {};
    return far + " against the rigid-contact engines' " + number_text(middle, 3) + " rad (median)";
}

}  // namespace cairn::scene_compare
