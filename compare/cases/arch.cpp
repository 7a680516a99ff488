// an arch under its own weight: stands (its crown settles elastically and stops) or collapses
#include <algorithm>
#include <cmath>

#include "analytic/block_limit_analysis.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "cases/structure_kinds.hpp"
#include "error.hpp"
#include "output/number_format.hpp"

namespace cairn::cases {

namespace {

/// whether a statically admissible state of the scene's blocks exists under gravity alone
bool limit_analysis_stands(const Scene& scene) {
    return oracle::collapse_multiplier(oracle::limit_blocks(scene), scene.gravity, Vec3::Zero(), scene.contact.friction)
        .stands_at_zero;
}

}  // namespace

CaseAnalysis analyse_arch(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const auto& v = scene.reference->values;
    if (!v.count("thickness")) throw Error(scene.source + ": an arch reference needs the value thickness (m)");
    const int crown = probe_index(scene, "crown");
    if (crown < 0) throw Error(scene.source + ": an arch reference needs a probe named crown");
    const bool admissible = limit_analysis_stands(scene);
    const bool stands = v.count("stands") ? v.at("stands") != 0.0 : admissible;
    const double t = v.at("thickness");
    CaseAnalysis r;
    const std::string la = "rigid-block limit analysis of the scene's blocks (μ = " + fixed_text(scene.contact.friction, 3) +
                           "): a statically admissible state under gravity " + (admissible ? "exists" : "does not exist");
    if (v.count("stands"))
        r.metrics.push_back(info("stands (1) or collapses (0), as the scene states", "", stands ? 1.0 : 0.0,
                                 admissible ? 1.0 : 0.0, la));
    Series z = probe_series(s, crown, 2, true);
    for (double& y : z.y) y = -y;   // settlement: downward positive
    r.measured = z;
    r.quantity = "settlement of the crown, m";
    const double end = s.back().t, half = 0.5 * end;
    auto at = [&](double time) {
        size_t i = std::lower_bound(z.t.begin(), z.t.end(), time) - z.t.begin();
        return z.y[std::min(i, z.y.size() - 1)];
    };
    const double first = at(half), last = z.y.back();
    if (!stands) {
        r.metrics.push_back(at_least("crown settlement", "m", last, t,
                                     "thinner than the limit-analysis minimum (compare/analytic): no thrust line fits, "
                                     "a 5-hinge mechanism forms and the crown falls by more than the thickness"));
        auto fall = crossings(z, t, Crossing::up);
        if (!fall.empty()) r.event_time = fall.front(), r.has_event = true;
        return r;
    }
    // standing: the joints close elastically (about a millimetre at kn = 1e9 N/m³) and the
    // settlement stops: the second half of the run adds at most a tenth of the first half's
    r.metrics.push_back(at_most("crown settlement", "m", last, 0.0, 0.05 * t,
                                "thicker than the limit-analysis minimum: a thrust line fits, only elastic closure "
                                "of the joints; bound 5 % of the thickness"));
    r.metrics.push_back(at_most("settlement in the second half", "m", last - first, 0.0, 0.1 * std::abs(first) + 1e-4,
                                "the settlement stops: at most a tenth of the first half's, plus 0.1 mm"));
    // energy closed: the balance error against the energy of the motion (kinetic, contact and
    // strain at their largest, plus the potential exchanged)
    double motion = 0.0, pmin = INFINITY, pmax = -INFINITY, err = 0.0;
    const double total0 = s.front().energy.total();
    for (const auto& x : s) {
        motion = std::max(motion, x.energy.kinetic + x.energy.contact + x.energy.strain);
        pmin = std::min(pmin, x.energy.potential), pmax = std::max(pmax, x.energy.potential);
        err = std::max(err, std::abs(x.energy.total() - total0));
    }
    // judged where the backend books every loss (dem); a rigid engine's contact dissipates what
    // it does not book (its balance error is then what the settling lost: shown)
    const double closure = err / std::max(1e-12, motion + pmax - pmin);
    if (contact.penalty && contact.point_springs)
        r.metrics.push_back(at_most("energy balance error / motion energy", "", closure, 0.0, 1e-3,
                                    "0.1 % of the energy of the motion"));
    else
        r.metrics.push_back(info("energy balance error / motion energy", "", closure, 0.0,
                                 "not judged: this engine does not book what its contact dissipates"));
    return r;
}

// kind "arch": no reference curve
static const CaseKind& arch_kind() {
    static const FunctionKind k("arch", {"stands", "thickness"}, analyse_arch, nullptr, rigid_contact_only,
                                "crown fell by the thickness", [](const Scene& s) { require_drive_modelled(s, "arch", {}); });
    return k;
}

namespace {
const KindRegistration arch_registered(arch_kind);
}  // namespace

}  // namespace cairn::cases
