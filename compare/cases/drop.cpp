// cases (a) stability and (b) impact: a block on (or dropped onto) the penalty springs of a face
#include <cmath>

#include "analytic/oracles.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "output/number_format.hpp"

namespace cairn::cases {

namespace {

/// the 1-DOF oracle of the scene: the reference block on K = kn·A with the scene's dashpot
oracle::DampedDrop drop_oracle(const Scene& scene) {
    const int a = scene.reference->block;
    const double m = block_mass(scene, a), k = scene.contact.kn * contact_area(scene);
    const double gap = scene.reference->kind == "impact" ? scene.reference->values.at("gap") : 0.0;
    return {m, k, dashpot(scene, k, m), gravity(scene), gap};
}

/// height of the block's bottom above the contact plane (negative = penetration), from the
/// probe node10 (or the centre of mass) relative to its start, against gravity
metrics::Series height_series(const Scene& scene, const std::vector<Sample>& s, double gap) {
    metrics::Series h = rise_series(scene, s, probe_index(scene, "node10"), free_index(scene, scene.reference->block));
    for (double& y : h.y) y += gap;
    return h;
}

std::vector<double> drop_curve(const Scene& scene, ContactKind, const std::vector<double>& t) {
    auto h = drop_oracle(scene).heights(t);
    if (scene.reference->kind == "rest")
        for (double& y : h) y = -y;   // plotted as penetration
    return h;
}

CaseAnalysis analyse_drop(const Scene& scene, const std::vector<Sample>& s, ContactKind) {
    using namespace metrics;
    const oracle::DampedDrop o = drop_oracle(scene);
    const bool rest = scene.reference->kind == "rest";
    CaseAnalysis r;
    Series h = height_series(scene, s, o.gap);
    r.analytic = drop_curve(scene, {}, h.t);
    r.analytic_label = "1-DOF spring-dashpot oracle, K = kn·A";
    const std::string oracle_note = "K = kn·A = " + message_number(o.stiffness, 6) + " N/m, m = " +
                                    message_number(o.mass, 6) + " kg";
    if (rest) {
        Series d = h;
        for (double& y : d.y) y = -y;
        r.quantity = "penetration of A (node10), m";
        const double eq = o.mass * o.g / o.stiffness;
        const double hi = max_value(d), lo = min_value(d), mid = 0.5 * (hi + lo);
        r.metrics.push_back(relative("equilibrium penetration", "m", mid, eq, 0.01,
                                     "mg/K (" + oracle_note + "), mid-swing; 1 %"));
        r.metrics.push_back(relative("peak penetration", "m", hi, 2.0 * eq, 0.01,
                                     "2mg/K, released just touching; 1 % as the equilibrium"));
        oracle::RestingBlock rb{o.mass, o.stiffness, o.g};
        double period = period_from_crossings(d, mid);
        if (period > 0.0)
            r.metrics.push_back(relative("period", "s", period, rb.period(), 0.01,
                                         "2π√(m/K); 1 %"));
        else
            r.metrics.push_back(missing("period", "s", rb.period(), 0.01, Check::relative, "no oscillation found"));
        auto peaks = extrema(d, true, 0.25 * eq);
        if (!peaks.empty()) { r.event_time = peaks.front().t; r.has_event = true; }
        r.measured = d;
        return r;
    }
    r.quantity = "height of A's bottom above B (node10), m";
    r.measured = h;
    const auto b = o.first_bounce();
    const double v0 = std::sqrt(2.0 * o.g * o.gap);
    const auto touch = crossings(h, 0.0, Crossing::down);
    const auto leave = crossings(h, 0.0, Crossing::up);
    if (touch.empty()) {
        r.metrics.push_back(missing("first contact", "s", v0 / o.g, 0.01, Check::relative, "A never touched B"));
        return r;
    }
    r.event_time = touch[0];
    r.has_event = true;
    r.metrics.push_back(relative("first contact", "s", touch[0], v0 / o.g, 0.01, "free fall √(2h/g)"));
    const double t_end = touch.size() > 1 ? touch[1] : h.t.back();
    r.metrics.push_back(relative("peak penetration", "m", -min_value(h, touch[0], t_end), b.max_penetration, 0.02,
                                 "1-DOF contact phase with release (" + oracle_note + "); 2 %"));
    if (touch.size() > 1)
        r.metrics.push_back(relative("bounce period", "s", touch[1] - touch[0], o.bounce_period(), 0.01,
                                     "contact time + 2 e v0/g of the 1-DOF oracle; 1 %"));
    else
        r.metrics.push_back(missing("bounce period", "s", o.bounce_period(), 0.01, Check::relative,
                                    "no second contact within the run"));
    if (!leave.empty() && touch.size() > 1) {
        double apex = max_value(h, leave[0], touch[1]);
        r.metrics.push_back(relative("rebound ratio", "", apex / o.gap, b.restitution * b.restitution, 0.02,
                                     "e² with e = " + message_number(b.restitution, 6) +
                                         " (gravity + release rule); 2 % as the penetration"));
    } else {
        r.metrics.push_back(missing("rebound ratio", "", b.restitution * b.restitution, 0.02, Check::relative,
                                    "A did not leave B and come back within the run"));
    }
    return r;
}

}  // namespace

// kinds "rest" (a) and "impact" (b): the reference is the penalty spring kn·A
static const CaseKind& rest_kind() {
    static const FunctionKind k("rest", {}, analyse_drop, drop_curve, matched_contact_only, "first peak penetration",
                                [](const Scene& s) { require_drive_modelled(s, "rest", {}); });
    return k;
}

static const CaseKind& impact_kind() {
    static const FunctionKind k("impact", {"gap"}, analyse_drop, drop_curve, matched_contact_only, "first contact",
                                [](const Scene& s) { require_drive_modelled(s, "impact", {}); });
    return k;
}

namespace {
const KindRegistration rest_registered(rest_kind);
const KindRegistration impact_registered(impact_kind);
}  // namespace

}  // namespace cairn::cases
