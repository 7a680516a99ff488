// case (c): a block pushed by H on a flat base, sliding (H > μW) or holding (H < μW)
#include <algorithm>
#include <cmath>

#include "analytic/oracles.hpp"
#include "cases/case_util.hpp"
#include "cases/kinds.hpp"

namespace cairn::cases {

namespace {

/// the load on the reference block (the first one acting on it), or nullptr
const LoadDef* pull(const Scene& scene) {
    for (const auto& l : scene.loads)
        if (l.block == scene.reference->block) return &l;
    return nullptr;
}

}  // namespace

std::vector<double> friction_curve(const Scene& scene, const std::vector<double>& t) {
    const int a = scene.reference->block;
    const double m = block_mass(scene, a), g = gravity(scene), H = scene.reference->values.at("force");
    const LoadDef* l = pull(scene);
    std::vector<double> out;
    if (scene.reference->kind == "slide") {
        const double acc = oracle::pulled_block_acceleration(m, g, H, scene.contact.friction);
        for (double x : t) out.push_back(0.5 * acc * x * x);
    } else {
        // quasi-static elastic shear H(t)/(ks·A)
        const double k = scene.contact.ks * contact_area(scene);
        for (double x : t) out.push_back((l ? l->factor(x) : 1.0) * H / k);
    }
    return out;
}

CaseAnalysis analyse_friction(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const int a = scene.reference->block;
    const double m = block_mass(scene, a), g = gravity(scene), H = scene.reference->values.at("force");
    const double T = s.back().t;
    CaseAnalysis r;
    if (scene.reference->kind == "slide") {
        Series x = com_series(s, free_index(scene, a), 0, true);
        r.quantity = "x displacement of A's centre of mass, m";
        r.measured = x;
        r.analytic = friction_curve(scene, x.t);
        r.analytic_label = "s = a t²/2, a = (H/W − μ) g";
        const double acc = oracle::pulled_block_acceleration(m, g, H, scene.contact.friction);
        // skip the first 10 % (the shear spring's start-up transient), then fit x = c0 + c1 t + c2 t²
        auto c = polyfit(x, 2, 0.1 * T, T);
        r.metrics.push_back(relative("sliding acceleration", "m/s²", 2.0 * c[2], acc, 0.01,
                                     "(H/W − μ) g, quadratic fit over the last 90 % of the run; issue 5: 1 %"));
        auto half = crossings(x, 0.5 * 0.5 * acc * T * T, Crossing::up);
        if (!half.empty()) { r.event_time = half[0]; r.has_event = true; }
        return r;
    }
    int p = probe_index(scene, "base");
    Series u = p >= 0 ? probe_series(s, p, 0, true) : com_series(s, free_index(scene, a), 0, true);
    r.quantity = "x displacement of A's base centre, m";
    r.measured = u;
    r.analytic = friction_curve(scene, u.t);
    r.analytic_label = "quasi-static elastic shear H(t)/(ks·A)";
    const double k = scene.contact.ks * contact_area(scene), elastic = H / k;
    const LoadDef* l = pull(scene);
    const double settled = l ? l->start + l->ramp : 0.0;
    const double peak = std::max(std::abs(max_value(u)), std::abs(min_value(u)));
    r.metrics.push_back(info("largest displacement", "m", peak, NAN, "elastic shear plus any slip"));
    // holding means no progressive slip once the load is constant: the drift of a straight-line
    // fit over the second half after the ramp (an undamped shear oscillation averages out)
    const double t0 = settled + 0.5 * (T - settled);
    const double drift = polyfit(u, 1, t0, T)[1] * (T - t0);
    r.metrics.push_back(absolute("slip while held", "m", drift, 0.0, 0.05 * elastic,
                                 "linear drift over the second half after the ramp; 5 % of the elastic "
                                 "shear H/(ks·A) = " + std::to_string(elastic) + " m"));
    if (contact.penalty) {
        // the undamped shear spring oscillates about H/k: its mean over the second half
        r.metrics.push_back(relative("elastic shear displacement", "m", mean_value(u, t0, T), elastic, 0.02,
                                     "H/(ks·A) with the whole face in contact; mean over the second half after the ramp, where "
                                     "the residual oscillation (≤ 6.6 % of it) averages out to < 1 %"));
    }
    return r;
}

}  // namespace cairn::cases
