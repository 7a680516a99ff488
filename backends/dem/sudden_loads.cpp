// the first load step after t = 0 faster than the contact springs' period
#include "sudden_loads.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/hexahedron.hpp"

namespace cairn::dem {

namespace {

/// the first time (s) after 0 at which load `l` changes by more than `jump` (its factor's units)
/// within `period`, or a negative number
double first_jump(const LoadDef& l, double period, double jump) {
    if (!l.history) {
        if (l.start > 0.0 && l.ramp < period && 1.0 > jump) return l.start;
        return -1.0;
    }
    // the history at (t − start), zero outside its span, scaled by the ramp (a ramp slower than
    // the period smooths the first jump)
    const TimeSeries& h = *l.history;
    const size_t n = h.time.size();
    if (n == 0) return -1.0;
    // segment i runs from sample i − 1 to sample i; the first and the last are the steps from
    // and to the zero outside the span, at its ends
    for (size_t i = 0; i <= n; ++i) {
        const double t0 = h.time[i == 0 ? 0 : i - 1], t1 = h.time[i == n ? n - 1 : i];
        const double v0 = i == 0 ? 0.0 : h.value[i - 1], v1 = i == n ? 0.0 : h.value[i];
        const double when = l.start + t0;
        if (when <= 0.0) continue;   // at t = 0 the settling takes it in
        const double scale = l.ramp > period ? std::min(1.0, (when - l.start) / l.ramp) : 1.0;
        if (t1 - t0 < period && std::abs(v1 - v0) * scale > jump) return when;
    }
    return -1.0;
}

}  // namespace

std::optional<SuddenLoad> first_sudden_load(const Scene& scene, double period) {
    std::optional<SuddenLoad> first;
    const double g = scene.gravity.norm();
    for (size_t k = 0; k < scene.loads.size(); ++k) {
        const LoadDef& l = scene.loads[k];
        const BlockDef& b = scene.blocks.at(size_t(l.block));
        if (b.fixed || !(l.force.norm() > 0.0)) continue;
        const double weight = mass_properties(b.corners, scene.materials.at(size_t(b.material)).density).mass * g;
        const double t = first_jump(l, period, 0.05 * weight / l.force.norm());
        if (t > 0.0 && (!first || t < first->time)) first = SuddenLoad{t, int(k)};
    }
    return first;
}

}  // namespace cairn::dem
