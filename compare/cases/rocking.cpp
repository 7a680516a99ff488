// case (e): a block released tilted on one base edge rocks (Housner 1963)
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analytic/oracles.hpp"
#include "cases/case_util.hpp"
#include "cases/kinds.hpp"

namespace cairn::cases {

namespace {

/// the impact velocity ratio that applies: Housner's for rigid contact, 1 for undamped penalty
/// contact (no loss), none (NaN) for damped penalty contact
double ratio_for(const Scene& scene, ContactKind contact, const oracle::HousnerBlock& hb) {
    if (!contact.penalty) return hb.velocity_ratio();
    return scene.contact.damping_rule == ContactDampingRule::none ? 1.0 : NAN;
}

}  // namespace

std::vector<double> rocking_curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) {
    const auto hb = housner_block(scene);
    double r = ratio_for(scene, contact, hb);
    // damped penalty contact: no closed form; the curve shown is Housner's rigid impact
    if (!std::isfinite(r)) r = hb.velocity_ratio();
    return hb.angles(scene.reference->values.at("theta0"), r, t);
}

CaseAnalysis analyse_rocking(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const auto hb = housner_block(scene);
    const double th0 = scene.reference->values.at("theta0"), a = hb.alpha();
    const double r_ref = ratio_for(scene, contact, hb);
    const bool has_r = std::isfinite(r_ref);
    CaseAnalysis out;
    Series th = angle_series(s, free_index(scene, scene.reference->block), rocking_axis(scene));
    out.quantity = "rocking angle θ of A, rad";
    out.measured = th;
    out.analytic = rocking_curve(scene, contact, th.t);
    out.analytic_label = has_r ? (contact.penalty ? "Housner, no impact loss (r = 1)"
                                                  : "Housner, rigid impact (r = " + std::to_string(r_ref) + ")")
                               : "Housner, rigid impact (guide only: no oracle for damped contact)";
    char key[64];
    std::snprintf(key, sizeof key, "Housner r = %.3g", std::isfinite(r_ref) ? r_ref : hb.velocity_ratio());
    out.analytic_key = key;
    const double tol = contact.penalty ? 0.02 : 0.01;
    const std::string why = contact.penalty
        ? "issue 5: DEM within 2 % at the paper's kn (edge on a face, physics.md)"
        : "issue 5: rigid-contact engines within 1 %";
    const double t1 = hb.first_impact(th0);
    auto cross = crossings(th, 0.0, Crossing::any);
    if (cross.empty()) {
        out.metrics.push_back(missing("first impact", "s", t1, tol, Check::relative, "A never came back upright"));
        return out;
    }
    out.event_time = cross[0];
    out.has_event = true;
    out.metrics.push_back(relative("first impact", "s", cross[0], t1, tol, "Housner exact t1; " + why));

    // amplitude after the first impact: the extremum of |θ| between the 1st and 2nd crossings
    const double t_end = cross.size() > 1 ? cross[1] : th.t.back();
    double th1 = 0.0, t_th1 = 0.0;
    for (size_t i = 0; i < th.t.size(); ++i)
        if (th.t[i] > cross[0] && th.t[i] < t_end && std::abs(th.y[i]) > th1) { th1 = std::abs(th.y[i]); t_th1 = th.t[i]; }
    const bool swung = cross.size() > 1 || (t_th1 > 0.0 && t_th1 < th.t.back() - 2.0 * (th.t[1] - th.t[0]));
    const double th1_ref = has_r ? hb.amplitude_after(th0, 1, r_ref) : NAN;
    const std::string amp_basis = has_r
        ? (contact.penalty ? "undamped penalty contact loses no energy: θ1 = θ0; 2 %"
                           : "Housner's impact law; 2 %: engines.md, dt 1e-4 s gives < 2 % amplitude error")
        : "no closed form for a damped penalty contact";
    if (!swung) {
        out.metrics.push_back(missing("amplitude after 1st impact", "rad", th1_ref, 0.02,
                                      has_r ? Check::relative : Check::info, "the run ended before the swing did"));
        return out;
    }
    if (has_r) out.metrics.push_back(relative("amplitude after 1st impact", "rad", th1, th1_ref, 0.02, amp_basis));
    else out.metrics.push_back(info("amplitude after 1st impact", "rad", th1, NAN, amp_basis));
    // the impact's angular-velocity ratio from the energy before and after (exact for a rigid block)
    const double r = std::sqrt(std::max(0.0, (std::cos(a - th1) - std::cos(a)) / (std::cos(a - th0) - std::cos(a))));
    if (has_r) out.metrics.push_back(relative("impact velocity ratio", "", r, r_ref, 0.02,
                                              "from θ0 and θ1 via Housner's energy relation; 2 % as the amplitude"));
    else out.metrics.push_back(info("impact velocity ratio", "", r, hb.velocity_ratio(),
                                    "from θ0, θ1; shown beside Housner's rigid value"));
    if (cross.size() > 1) {
        const double half = cross[1] - cross[0];
        if (has_r) out.metrics.push_back(relative("half cycle (1st to 2nd impact)", "s", half,
                                                  2.0 * hb.first_impact(th1_ref), tol, "2 t1(θ1); " + why));
        else out.metrics.push_back(info("half cycle (1st to 2nd impact)", "s", half, NAN, "no closed form"));
    } else if (has_r) {
        out.metrics.push_back(missing("half cycle (1st to 2nd impact)", "s", 2.0 * hb.first_impact(th1_ref), tol,
                                      Check::relative, "no second impact within the run"));
    }
    if (cross.size() > 2) {
        double th2 = 0.0;
        const double t3 = cross[2];
        for (size_t i = 0; i < th.t.size(); ++i)
            if (th.t[i] > cross[1] && th.t[i] < t3) th2 = std::max(th2, std::abs(th.y[i]));
        out.metrics.push_back(info("amplitude after 2nd impact", "rad", th2,
                                   has_r ? hb.amplitude_after(th0, 2, r_ref) : NAN, "amplitude sequence"));
    }
    return out;
}

}  // namespace cairn::cases
