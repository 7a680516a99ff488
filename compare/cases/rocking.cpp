// case (e): a block released tilted on one base edge rocks (Housner 1963), judged against the
// reference that models each variant's contact: Housner's rigid impact for rigid contact, the
// spring block (oracle::SpringBlock: the same point springs, integrated independently) for the
// hitting-point springs of dem's paper scheme, the rigid block on a Winkler base
// (oracle::WinklerRocking) for dem's overlap contact; an engine's matched contact has no reference
// after the first impact
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analytic/oracles.hpp"
#include "analytic/spring_block.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "cases/winkler_model.hpp"
#include "error.hpp"
#include "output/number_format.hpp"

namespace cairn::cases {

namespace {

/// the spring block of the scene's reference block: its base rows across the rocking axis (the
/// hitting grid of a rigid face, or of each mesh face of a deformable block) with the scene's law
oracle::SpringBlock spring_block(const Scene& scene, ContactKind contact) {
    const int a = scene.reference->block;
    const BlockDef& d = scene.blocks.at(size_t(a));
    const Vec3 axis = rocking_axis_block(scene), across = axis.cross(Vec3::UnitZ()).normalized();
    double lo = 1e300, hi = -1e300, alo = 1e300, ahi = -1e300, zlo = 1e300, zhi = -1e300;
    for (const auto& c : d.corners) {
        lo = std::min(lo, c.dot(across)), hi = std::max(hi, c.dot(across));
        alo = std::min(alo, c.dot(axis)), ahi = std::max(ahi, c.dot(axis));
        zlo = std::min(zlo, c.z()), zhi = std::max(zhi, c.z());
    }
    // mesh divisions along the block-frame axis that lies across the rocking axis
    int div = 1;
    for (int k = 0; k < 3; ++k)
        if (std::abs(across[k]) > 0.5) div = contact.divisions[size_t(k)];
    oracle::SpringBlock sb{hi - lo, zhi - zlo, block_mass(scene, a), gravity(scene),
                           scene.contact.kn, scene.contact.ks, scene.contact.friction,
                           oracle::spring_rows(hi - lo, ahi - alo, div, scene.contact.grid_spacing)};
    sb.zeta = scene.contact.damping_rule == ContactDampingRule::ratio ? scene.contact.damping : 0.0;
    return sb;
}

/// which reference models the variant after its first impact
enum class Model { housner, springs, winkler, none };

Model model_for(const Scene& scene, ContactKind contact) {
    if (!contact.penalty) return Model::housner;
    if (!contact.point_springs) return Model::none;
    // the overlap scheme integrates kn over the face: the Winkler base (which says when it cannot)
    if (scene.contact.scheme == ContactScheme::overlap)
        return winkler_unmodelled(scene, contact, rocking_axis_block(scene)).empty() ? Model::winkler : Model::none;
    // the spring block carries the ratio rule's dashpots; a damping time γ it does not model
    if (scene.contact.damping_rule != ContactDampingRule::time) return Model::springs;
    return Model::none;
}

/// the Winkler base's rocking from the scene's release, sampled every millisecond, to `until` (s)
oracle::WinklerTrace winkler_trace(const Scene& scene, ContactKind contact, double until) {
    return winkler_model(scene, contact, rocking_axis_block(scene))
        .rock(scene.reference->values.at("theta0"), until + 1e-9, 1e-3);
}

/// why a variant of Model::none has no reference after its first impact
std::string unmodelled_reason(const Scene& scene, ContactKind contact) {
    if (contact.point_springs && scene.contact.scheme == ContactScheme::overlap)
        return "no reference models it: " + winkler_unmodelled(scene, contact, rocking_axis_block(scene));
    if (contact.point_springs) return "no reference models it: the spring block carries dashpots by damping ratio, not by damping time";
    return "no reference models it: the engine's matched contact reproduces kn·A of a face (static "
           "penetration, frequency), not the springs along the hitting edge nor their loss at an impact";
}

/// largest |θ| between times a and b
double amplitude(const metrics::Series& th, double a, double b) {
    double m = 0.0;
    for (size_t i = 0; i < th.t.size(); ++i)
        if (th.t[i] > a && th.t[i] < b) m = std::max(m, std::abs(th.y[i]));
    return m;
}

std::vector<double> rocking_curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) {
    const auto hb = housner_block(scene);
    const double th0 = scene.reference->values.at("theta0");
    const Model model = model_for(scene, contact);
    if (model == Model::springs) return spring_block(scene, contact).angles(th0, t);
    if (model == Model::winkler)
        return t.empty() ? std::vector<double>{} : winkler_angles(winkler_trace(scene, contact, t.back()), t);
    // rigid contact; for a matched engine the curve is Housner's as a guide only
    return hb.angles(th0, hb.velocity_ratio(), t);
}

CaseAnalysis analyse_rocking(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const auto hb = housner_block(scene);
    const double th0 = scene.reference->values.at("theta0"), a = hb.alpha();
    const Model model = model_for(scene, contact);
    const std::string no_model_reason = model == Model::none ? unmodelled_reason(scene, contact) : "";
    CaseAnalysis out;
    Series th = angle_series(s, free_index(scene, scene.reference->block), rocking_axis(scene), upright_orientation(scene));
    out.quantity = "rocking angle θ of A, rad";
    out.measured = th;
    const double duration = th.t.back();

    // the reference's impacts and amplitudes
    std::vector<double> ref_impacts, ref_amps;
    if (model == Model::springs) {
        const auto tr = spring_block(scene, contact).rock(th0, duration + 1e-9, 1e-4);
        ref_impacts = tr.impacts;
        ref_amps = tr.amplitudes;
        out.analytic = oracle::angles_at(tr, th.t);
        out.analytic_label = "spring block: the rigid block on the same point springs (ζ = " +
                             std::to_string(scene.contact.damping_rule == ContactDampingRule::ratio ? scene.contact.damping : 0.0) +
                             "), integrated independently";
        out.analytic_key = "spring block";
    } else if (model == Model::winkler) {
        const auto tr = winkler_trace(scene, contact, duration);
        ref_impacts = tr.crossings;
        ref_amps = tr.amplitudes;
        out.analytic = winkler_angles(tr, th.t);
        out.analytic_label = "rigid block on a no-tension Winkler base of modulus kn (dem's overlap contact: shear "
                             "springs and dashpots as dem's, per sub-contact), integrated independently";
        out.analytic_key = "Winkler base";
    } else {
        // Housner's swings that end within the run: impact k+1 comes 2·t1(θk) after impact k
        ref_impacts = {hb.first_impact(th0)};
        for (int n = 1; n <= 3; ++n) {
            const double amp = hb.amplitude_after(th0, n), next = ref_impacts.back() + 2.0 * hb.first_impact(amp);
            if (next > duration) break;
            ref_amps.push_back(amp);
            ref_impacts.push_back(next);
        }
        out.analytic = hb.angles(th0, hb.velocity_ratio(), th.t);
        char key[64];
        std::snprintf(key, sizeof key, "Housner r = %.3g", hb.velocity_ratio());
        out.analytic_key = key;
        out.analytic_label = model == Model::housner ? "Housner, rigid impact (r = " + std::to_string(hb.velocity_ratio()) + ")"
                                                     : "Housner, rigid impact (guide only: no reference for the engine's matched contact)";
    }
    const double tol = contact.penalty ? 0.02 : 0.01;
    const std::string why = contact.penalty ? "penalty contact: 2 %" : "rigid-contact engines: 1 %";

    // first impact: free rocking about the edge before it, Housner's exact t1 for every contact (the
    // penalty edge sinking into the springs delays it: 0.13 % for reading B at kn = 3e7, 1.4 % for the
    // slender block, within the 2 % of penalty contact; the spring block's t1 is shown beside it)
    const double t1 = hb.first_impact(th0);
    std::string t1_basis = "Housner exact t1; " + why;
    if (model == Model::springs && !ref_impacts.empty())
        t1_basis += "; spring block " + message_number(ref_impacts[0], 6) + " s";
    if (model == Model::winkler && !ref_impacts.empty()) {
        t1_basis += "; the Winkler base of the same kn " + message_number(ref_impacts[0], 6) +
                    " s (its delay falls as kn^(-1/2))";
        // soft shear springs let the pivot slide as the block rocks: it comes back early
        // (a 0.46 × 0.93 × 2 m block at ks = 0.04 kn: −4.0 %, +0.78 % at ks = kn)
        if (scene.contact.ks < 0.1 * scene.contact.kn)
            t1_basis += "; ks = " + message_number(scene.contact.ks / scene.contact.kn, 2) +
                        " kn: the pivot slides on its shear springs as it rocks (docs/dem.md, \"Set ks with kn\")";
    }
    auto cross = crossings(th, 0.0, Crossing::any);
    if (cross.empty()) {
        out.metrics.push_back(missing("first impact", "s", t1, tol, Check::relative, "A never came back upright"));
        return out;
    }
    out.event_time = cross[0];
    out.has_event = true;
    if (model == Model::winkler && !ref_impacts.empty()) {
        // dem's overlap contact is the joint's own physics: the Winkler base of its kn, whose delay
        // past Housner's rigid t1 is no error of the engine (a 0.15 m wide, 1.2 m high block at
        // kn 1e10: +2.6 %, followed by dem to 1e-6); Housner's t1 beside it
        std::string basis = "the rigid block on a no-tension Winkler base of the same kn (dem's overlap contact); " + why +
                            "; Housner's rigid t1 " + message_number(t1, 6) + " s, " +
                            percent_text(ref_impacts[0] / t1 - 1.0) + " from it (the joint's compliance, falling as kn^(-1/2))";
        if (scene.contact.ks < 0.1 * scene.contact.kn)
            basis += "; ks = " + message_number(scene.contact.ks / scene.contact.kn, 2) +
                     " kn: the pivot slides on its shear springs as it rocks (docs/dem.md, \"Set ks with kn\")";
        out.metrics.push_back(relative("first impact", "s", cross[0], ref_impacts[0], tol, basis));
        out.metrics.push_back(info("first impact against Housner", "s", cross[0], t1,
                                   "Housner's exact t1 of the rigid block on a rigid base, shown: dem's overlap contact is "
                                   "judged against its Winkler base"));
    } else {
        out.metrics.push_back(relative("first impact", "s", cross[0], t1, tol, t1_basis));
    }

    // amplitudes after each impact: the extremum of |θ| between crossings (as many as the scene's
    // `impacts` asks, at least two)
    const auto imp = scene.reference->values.find("impacts");
    const int housner_impacts = imp == scene.reference->values.end() ? 0 : int(std::lround(imp->second));
    const size_t wanted = size_t(std::max(2, housner_impacts));
    const double dt = th.t.size() > 1 ? th.t[1] - th.t[0] : 0.0;
    std::vector<double> amps;
    for (size_t k = 0; k < wanted && k < cross.size(); ++k) {
        const double end = k + 1 < cross.size() ? cross[k + 1] : duration;
        const double m = amplitude(th, cross[k], end);
        // an unfinished swing counts once |θ| has turned back
        if (k + 1 < cross.size() || (m > 0.0 && std::abs(th.y.back()) < 0.5 * m && end > cross[k] + 2.0 * dt)) amps.push_back(m);
    }
    // a deformable block soft against its joints trades energy between its vibration and its rocking
    // at every impact: its swings after one are shown beside the rigid block's, not judged
    const std::string flexible = flexible_block_reason(scene, scene.reference->block, contact.deformable);
    const char* names[2] = {"amplitude after 1st impact", "amplitude after 2nd impact"};
    for (size_t k = 0; k < 2; ++k) {
        const double ref = k < ref_amps.size() ? ref_amps[k] : NAN;
        if (!flexible.empty() && model != Model::none) {
            if (k < amps.size()) out.metrics.push_back(info(names[k], "rad", amps[k], ref, flexible));
            continue;
        }
        if (model == Model::none) {
            if (k < amps.size()) out.metrics.push_back(not_comparable(names[k], "rad", amps[k], NAN, no_model_reason));
            continue;
        }
        const std::string basis = model == Model::housner ? "Housner's impact law; 2 %: dt 1e-4 s gives < 2 % amplitude error"
                                  : model == Model::winkler
                                      ? "Winkler base (dem's overlap contact, the same law per sub-contact); 2 %"
                                      : "spring block (same springs, same law, dt ≤ T/1000); 2 %";
        if (!std::isfinite(ref)) {
            if (k < amps.size())
                out.metrics.push_back(info(names[k], "rad", amps[k], NAN,
                                           "no reference amplitude: its swing does not end within the run, or it stops "
                                           "rocking before"));
            continue;
        }
        if (k < amps.size()) out.metrics.push_back(relative(names[k], "rad", amps[k], ref, 0.02, basis));
        else out.metrics.push_back(missing(names[k], "rad", ref, 0.02, Check::relative, "the run ended before this swing did"));
    }
    // a contact damped to Housner's loss (the ζ of calibrate_housner_damping): the penalty run is also
    // judged on Housner's amplitude sequence over the scene's `impacts`
    if (housner_impacts > 0 && contact.penalty && scene.contact.damping_rule == ContactDampingRule::ratio) {
        for (int k = 0; k < housner_impacts; ++k) {
            const std::string name = "Housner amplitude after impact " + std::to_string(k + 1);
            const double ref = hb.amplitude_after(th0, k + 1);
            if (!flexible.empty() && model != Model::none) {
                if (size_t(k) < amps.size()) out.metrics.push_back(info(name, "rad", amps[size_t(k)], ref, flexible));
                continue;
            }
            if (model == Model::none) {
                if (size_t(k) < amps.size()) out.metrics.push_back(not_comparable(name, "rad", amps[size_t(k)], ref, no_model_reason));
                continue;
            }
            const std::string basis = "contact damping ratio ζ = " + message_number(scene.contact.damping) +
                                      " as the scene gives it: judged against Housner's loss where ζ is calibrated to it "
                                      "for this block and kn (docs/validation.md, \"Rocking with Housner's loss on a penalty engine\"); 2 %";
            if (size_t(k) < amps.size()) out.metrics.push_back(relative(name, "rad", amps[size_t(k)], ref, 0.02, basis));
            else out.metrics.push_back(missing(name, "rad", ref, 0.02, Check::relative, "the run ended before this swing did"));
        }
    }
    if (amps.empty()) return out;

    // the impact's angular-velocity ratio from the energy before and after (exact for a rigid block)
    const double th1 = amps[0];
    const double r = std::sqrt(std::max(0.0, (std::cos(a - th1) - std::cos(a)) / (std::cos(a - th0) - std::cos(a))));
    if (model == Model::housner)
        out.metrics.push_back(relative("impact velocity ratio", "", r, hb.velocity_ratio(), 0.02,
                                       "from θ0 and θ1 via Housner's energy relation; 2 % as the amplitude"));
    else
        out.metrics.push_back(info("impact velocity ratio", "", r, hb.velocity_ratio(),
                                   "from θ0, θ1; shown beside Housner's rigid value"));
    // half cycle: free rocking from the measured amplitude θ1 to the next impact takes 2·t1(θ1),
    // whatever the impact did (judging with the reference's θ1 would count an amplitude miss twice).
    // On springs (the spring block, the Winkler base) the edge sinks in on the way out and back, which
    // Housner's t1 leaves out (+9 % on a 0.2 m wide block at kn 1e9): there the reference's own half
    // cycle, carried to the measured θ1 by the ratio of Housner's 2·t1 at the two amplitudes
    if (cross.size() > 1) {
        const double half = cross[1] - cross[0];
        const double housner_half = 2.0 * hb.first_impact(std::min(th1, 0.999 * a));
        if (model == Model::none)
            out.metrics.push_back(not_comparable("half cycle (1st to 2nd impact)", "s", half, 2.0 * hb.first_impact(th1), no_model_reason));
        else if (model != Model::housner && ref_impacts.size() > 1 && !ref_amps.empty()) {
            const double ref_half = (ref_impacts[1] - ref_impacts[0]) * housner_half /
                                    (2.0 * hb.first_impact(std::min(ref_amps[0], 0.999 * a)));
            if (!flexible.empty())
                out.metrics.push_back(info("half cycle (1st to 2nd impact)", "s", half, ref_half, flexible));
            else
                out.metrics.push_back(relative("half cycle (1st to 2nd impact)", "s", half, ref_half, tol,
                                               "the " + out.analytic_key + "'s half cycle " +
                                                   std::to_string(ref_impacts[1] - ref_impacts[0]) +
                                                   " s, carried to the measured θ1 by Housner's 2 t1(θ1); " + why));
        } else if (!flexible.empty())
            out.metrics.push_back(info("half cycle (1st to 2nd impact)", "s", half, housner_half, flexible));
        else
            out.metrics.push_back(relative("half cycle (1st to 2nd impact)", "s", half, housner_half,
                                           tol, "2 t1(θ1) with the measured θ1; " + why));
    }
    // energy closure (dem books every loss): the largest |E(t) − E0| with the dissipation counted,
    // against the rocking energy m g R [cos(α − θ0) − cos α]
    if (contact.point_springs && contact.penalty) {
        const double rock = block_mass(scene, scene.reference->block) * gravity(scene) * hb.radius() * (std::cos(a - th0) - std::cos(a));
        const double e0 = s.front().energy.total();
        double worst = 0.0;
        for (const auto& x : s) worst = std::max(worst, std::abs(x.energy.total() - e0));
        out.metrics.push_back(at_most("energy closure", "J", worst, 0.0, 0.01 * rock,
                                      "largest |E(t) + dissipated − E0|; 1 % of the rocking energy m g R [cos(α−θ0) − cos α] = " +
                                          std::to_string(rock) + " J"));
    }
    return out;
}

// Housner's rigid impact judges rigid contact when the scene's contact is undamped; the matched
// springs are judged on the first impact (and, damped, on Housner's calibrated loss)
std::vector<std::string> rocking_modes(const Scene& scene) {
    if (scene.contact.damping_rule != ContactDampingRule::none) return {"matched"};
    return {"rigid", "matched"};
}

/// refuses an `impacts` that is not a count, or that asks for Housner's amplitudes of a contact
/// without the damping ratio they are judged through
void check_impacts(const Scene& scene) {
    const auto it = scene.reference->values.find("impacts");
    if (it == scene.reference->values.end()) return;
    const double n = it->second;
    const std::string head = scene.source + ": reference.impacts = " + message_number(n, 6) + ": ";
    if (!(n >= 1.0 && n <= 100.0 && n == std::floor(n)))
        throw Error(head + "expected a count of impacts, a whole number from 1 to 100");
    if (scene.contact.damping_rule != ContactDampingRule::ratio)
        throw Error(head + "Housner's amplitudes after impacts are judged on a penalty contact damped by "
                           "[contact] damping_ratio (calibrated to Housner's loss, docs/validation.md); this scene has "
                           "none (the rigid engines' amplitudes are judged without it)");
}

}  // namespace

// kind "housner" (e)
static const CaseKind& housner_kind() {
    static const FunctionKind k("housner", {"theta0", "axis_x", "axis_y", "axis_z", "impacts"}, analyse_rocking,
                                rocking_curve, rocking_modes, "first impact",
                                [](const Scene& s) {
                                    require_drive_modelled(s, "housner", {});
                                    require_tilted_release(s, "housner");
                                    check_impacts(s);
                                });
    return k;
}

namespace {
const KindRegistration housner_registered(housner_kind);
}  // namespace

}  // namespace cairn::cases
