// kind "winkler_rocking": a block released tilted on one base edge rocks on a soft base, judged
// against oracle::WinklerRocking (the rigid block on a no-tension Winkler bed of modulus kn, with
// dem's shear springs and dashpots per sub-contact): the model of dem's overlap contact, whose
// normal force is the exact integral of kn·d. Housner's rigid-base times are shown beside it.
#include <algorithm>
#include <cmath>
#include <string>

#include "analytic/oracles.hpp"
#include "analytic/winkler_rocking.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "cases/winkler_model.hpp"
#include "metrics/signal.hpp"

namespace cairn::cases {

namespace {

/// the Winkler oracle of the reference block about the reference's rocking axis
oracle::WinklerRocking winkler_block(const Scene& scene, ContactKind contact) {
    return winkler_model(scene, contact, rocking_axis_block(scene));
}

/// why a variant has no reference here, or empty when the oracle models it
std::string unmodelled(const Scene& scene, ContactKind contact) {
    return winkler_unmodelled(scene, contact, rocking_axis_block(scene));
}

double release_tilt(const Scene& scene) { return scene.reference->values.at("theta0"); }

std::vector<double> winkler_curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) {
    if (t.empty() || !unmodelled(scene, contact).empty()) return {};
    return winkler_angles(winkler_block(scene, contact).rock(release_tilt(scene), t.back() + 1e-9, 1e-3), t);
}

CaseAnalysis analyse_winkler(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    CaseAnalysis out;
    const double th0 = release_tilt(scene);
    const auto hb = housner_block(scene);
    Series th = angle_series(s, free_index(scene, scene.reference->block), rocking_axis(scene), upright_orientation(scene));
    out.quantity = "rocking angle θ of A, rad";
    out.measured = th;
    const auto cross = crossings(th, 0.0, Crossing::any);
    const double housner = hb.first_impact(th0);
    if (!cross.empty()) {
        out.event_time = cross[0];
        out.has_event = true;
    }
    const std::string why = unmodelled(scene, contact);
    if (!why.empty()) {
        if (!cross.empty()) out.metrics.push_back(not_comparable("first impact", "s", cross[0], housner, why));
        return out;
    }
    const auto tr = winkler_block(scene, contact).rock(th0, th.t.back() + 1e-9, 1e-3);
    out.analytic = winkler_angles(tr, th.t);
    out.analytic_key = "Winkler base";
    out.analytic_label = "rigid block on a no-tension Winkler base of modulus kn (shear springs and dashpots as dem's, "
                         "per sub-contact), integrated independently";
    // first impact: θ passes 0. dem follows the oracle within 0.02 % at kn 3e7 to 3e9, rigid and
    // deformable (tests/backends/dem/test_dem_winkler_rocking.cpp); 0.5 % as for penalty runs
    // near Housner, which is shown beside it
    const std::string basis = "Winkler base's first crossing; 0.5 %; Housner's rigid base " + std::to_string(housner) + " s";
    // whether it comes back upright at all: on a soft base a block may overturn where Housner's rocks
    out.metrics.push_back(absolute("comes back upright (1 yes, 0 no)", "", cross.empty() ? 0.0 : 1.0,
                                   tr.crossings.empty() ? 0.0 : 1.0, 0.0, "as the Winkler base does within the run"));
    if (tr.crossings.empty() || cross.empty()) return out;
    out.metrics.push_back(relative("first impact", "s", cross[0], tr.crossings[0], 0.005, basis));
    out.metrics.push_back(info("first impact against Housner", "s", cross[0], housner,
                               "Housner's rigid base: the soft base delays it by about kn^(-1/2)"));
    // the rebound: the largest |θ| between the first two crossings, through the impact, where every
    // sub-contact sticks and slips on its own: 2 % (measured within 0.9 %, rigid and deformable)
    const double end = cross.size() > 1 ? cross[1] : th.t.back();
    double amp = 0.0;
    for (size_t i = 0; i < th.t.size(); ++i)
        if (th.t[i] > cross[0] && th.t[i] < end) amp = std::max(amp, std::abs(th.y[i]));
    const std::string flexible = flexible_block_reason(scene, scene.reference->block, contact.deformable);
    if (!flexible.empty()) {
        out.metrics.push_back(info("amplitude after 1st impact", "rad", amp,
                                   tr.amplitudes.empty() ? NAN : tr.amplitudes[0], flexible));
    } else if (tr.amplitudes.empty()) {
        out.metrics.push_back(info("amplitude after 1st impact", "rad", amp, NAN,
                                   "the Winkler base does not come back within the run (past its slenderness it overturns)"));
    } else if (cross.size() > 1) {
        out.metrics.push_back(relative("amplitude after 1st impact", "rad", amp, tr.amplitudes[0], 0.02,
                                       "Winkler base (same law, per sub-contact); 2 %"));
    } else {
        out.metrics.push_back(missing("amplitude after 1st impact", "rad", tr.amplitudes[0], 0.02, Check::relative,
                                      "the run did not come back after its first impact"));
    }
    return out;
}

// only dem's penalty contact is modelled; the rigid engines run beside it with Housner's time shown
std::vector<std::string> rigid_beside(const Scene&) { return {"rigid"}; }

}  // namespace

static const CaseKind& winkler_kind() {
    static const FunctionKind k("winkler_rocking", {"theta0", "axis_x", "axis_y", "axis_z"}, analyse_winkler,
                                winkler_curve, rigid_beside, "first impact",
                                [](const Scene& s) {
                                    require_drive_modelled(s, "winkler_rocking", {});
                                    require_tilted_release(s, "winkler_rocking");
                                });
    return k;
}

namespace {
const KindRegistration winkler_registered(winkler_kind);
}  // namespace

}  // namespace cairn::cases
