// an arch under its own weight: stands (its crown settles elastically and stops) or collapses
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analytic/block_interfaces.hpp"
#include "analytic/block_limit_analysis.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "cases/structure_kinds.hpp"
#include "error.hpp"
#include "output/number_format.hpp"

namespace cairn::cases {

namespace {

/// the crown's motion from the joints' hinging, as a share of the thrust line's margin, up to
/// which a standing arch on dem's overlap contact is judged against the rigid blocks. Measured on
/// dem rigid: arches stood at shares 0.011 to 0.227 (a 15-voussoir pointed arch, t = 0.25 and
/// 0.3 m, kn 1e9 and 1e10; the 25-voussoir arch_thick at kn 3e10 and 1e11) and fell at 0.68 to
/// 10.5 (the pointed arch at t = 0.22 and 0.25 m, kn 1e9 and 1e10; arch_thick at kn 1e10): 0.15
/// stays 4.5 times below the least share that fell, the estimate being rough
constexpr double kHingeShare = 0.15;

/// whether a statically admissible state of the blocks exists under gravity alone, their joints
/// moved `inset` (m) inward from their edges
bool stands_under_gravity(const Scene& scene, const std::vector<oracle::LimitBlock>& blocks, double inset = 0.0) {
    return oracle::collapse_multiplier(blocks, scene.gravity, Vec3::Zero(), scene.contact.friction, inset).stands_at_zero;
}

/// how far the joints of a standing arch hinge on springs of modulus kn, against the room its
/// thrust line has: the thrust line's margin s (the largest inset of every joint from its edges at
/// which a thrust state still exists, by bisection to 1/1024 of the thickness t), and a joint's
/// rotation where its thrust N passes s from its edge, θ = 2N/(kn·D·(3s)²) (a no-tension Winkler
/// joint presses 3s of its depth D), with N half the free blocks' weight (the springers' vertical
/// reaction, a lower bound) and D the joints' median area over t; the crown moves about θ·L, L half
/// the span of the free blocks' centres
struct JointHinge {
    double margin = 0.0;     ///< s, m
    double rotation = 0.0;   ///< θ, rad
    double drift = 0.0;      ///< θ·L, m
};

JointHinge joint_hinge(const Scene& scene, const std::vector<oracle::LimitBlock>& blocks, double thickness) {
    JointHinge h;
    double hi = 0.5 * thickness;
    for (int i = 0; i < 10; ++i) {
        const double mid = 0.5 * (h.margin + hi);
        (stands_under_gravity(scene, blocks, mid) ? h.margin : hi) = mid;
    }
    std::vector<Corners> corners;
    std::vector<bool> fixed;
    double weight = 0.0, span = 0.0;
    Vec3 lo = Vec3::Constant(INFINITY), up = Vec3::Constant(-INFINITY);
    const Vec3 down = scene.gravity.normalized();
    for (const auto& b : blocks) {
        corners.push_back(b.corners), fixed.push_back(b.fixed);
        for (const auto& c : b.corners) lo = lo.cwiseMin(c), up = up.cwiseMax(c);
        if (b.fixed) continue;
        weight += b.mass * scene.gravity.norm();
        for (const auto& o : blocks) {
            if (o.fixed) continue;
            const Vec3 d = o.centre - b.centre;
            span = std::max(span, (d - d.dot(down) * down).norm());   // horizontal
        }
    }
    std::vector<double> areas;
    for (const auto& j : oracle::find_interfaces(corners, fixed, 1e-5 * (up - lo).norm())) areas.push_back(j.area);
    if (areas.empty() || !(h.margin > 0.0)) return h;
    std::nth_element(areas.begin(), areas.begin() + long(areas.size() / 2), areas.end());
    const double depth = areas[areas.size() / 2] / thickness, c = 3.0 * h.margin;
    h.rotation = 2.0 * (0.5 * weight) / (scene.contact.kn * depth * c * c);
    h.drift = h.rotation * 0.5 * span;
    return h;
}

}  // namespace

CaseAnalysis analyse_arch(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const auto& v = scene.reference->values;
    if (!v.count("thickness")) throw Error(scene.source + ": an arch reference needs the value thickness (m)");
    const int crown = probe_index(scene, "crown");
    if (crown < 0) throw Error(scene.source + ": an arch reference needs a probe named crown");
    const auto blocks = oracle::limit_blocks(scene);
    const bool admissible = stands_under_gravity(scene, blocks);
    const bool stands = v.count("stands") ? v.at("stands") != 0.0 : admissible;
    const double t = v.at("thickness");
    CaseAnalysis r;
    const std::string la = "rigid-block limit analysis of the scene's blocks (μ = " + fixed_text(scene.contact.friction, 3) +
                           "): a statically admissible state under gravity " + (admissible ? "exists" : "does not exist");
    if (v.count("stands"))
        r.metrics.push_back(info("stands (1) or collapses (0), as the scene states", "", stands ? 1.0 : 0.0,
                                 admissible ? 1.0 : 0.0, la));
    Series z = rise_series(scene, s, crown, -1);
    for (double& y : z.y) y = -y;   // settlement: along gravity positive
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
                                     "no thrust state (compare/analytic): thinner than the limit-analysis minimum, "
                                     "a 5-hinge mechanism forms, or joints of too low a friction slide; the crown "
                                     "falls by more than the thickness"));
        auto fall = crossings(z, t, Crossing::up);
        if (!fall.empty()) r.event_time = fall.front(), r.has_event = true;
        return r;
    }
    // standing: the joints close elastically (about a millimetre at kn = 1e9 N/m³) and the
    // settlement stops: the second half of the run adds at most a tenth of the first half's
    const std::string settles = "thicker than the limit-analysis minimum: a thrust line fits, only elastic closure of "
                                "the joints; bound 5 % of the thickness";
    std::string stops = "the settlement stops: at most a tenth of the first half's, plus 0.1 mm";
    if (!(contact.penalty && contact.point_springs))
        stops += "; an engine's iterative solver may leave the arch creeping (\"a structure held at rest\" in "
                 "the capability matrix)";
    std::string hinged;   // how far the joints hinge, where dem's overlap contact is judged
    bool judged = true;
    if (contact.penalty && contact.point_springs && scene.contact.scheme == ContactScheme::overlap) {
        // dem's overlap contact integrates kn over each joint: a joint whose thrust nears its edge
        // presses a short strip and turns, and the arch moves with it. Judged against the rigid
        // blocks only where that motion is small against the thrust line's margin
        const JointHinge h = joint_hinge(scene, blocks, t);
        char why[600];
        std::snprintf(why, sizeof why,
                      "the thrust line keeps s = %.3g m from the joints' edges; on springs of kn = %.3g N/m³ a joint "
                      "whose thrust passes there turns by about 2N/(kn·D·(3s)²) = %.3g rad (N = half the arch's "
                      "weight), and the crown moves by about %.3g m",
                      h.margin, scene.contact.kn, h.rotation, h.drift);
        // no margin (the scene says it stands where no thrust line keeps off the edges): nothing
        // to measure the hinging against, so not judged (0 ≤ 15 % of 0 passed before)
        judged = h.margin > 0.0 && h.drift <= kHingeShare * h.margin;
        const std::string share = fixed_text(100 * kHingeShare, 0) + " % of s";
        if (judged)
            hinged = std::string(why) + ", within " + share;
        else if (!(h.margin > 0.0))
            hinged = std::string("not judged: ") + why +
                     ": no thrust line keeps off the joints' edges, so nothing bounds their hinging (the rigid-block "
                     "analysis finds no margin where the scene says the arch stands)";
        else
            hinged = std::string("not judged: ") + why + ", more than " + share +
                     ": the joints' compliance decides whether it stands, which the rigid-block analysis leaves out (a "
                     "stiffer kn brings it back)";
    }
    if (!judged) {
        r.metrics.push_back(info("crown settlement", "m", last, 0.0, hinged + "; " + settles));
        r.metrics.push_back(info("settlement in the second half", "m", last - first, 0.0, stops));
    } else {
        const std::string basis = hinged.empty() ? settles : settles + "; " + hinged;
        r.metrics.push_back(at_most("crown settlement", "m", last, 0.0, 0.05 * t, basis));
        r.metrics.push_back(
            at_most("settlement in the second half", "m", last - first, 0.0, 0.1 * std::abs(first) + 1e-4, stops));
    }
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
