// kind "ground_rocking": one rectangular block standing on a horizontal base, driven by its ground
// motion (loads at its centre of mass) along one of its horizontal axes, uplifts and rocks about a
// bottom edge. Judged against Housner's equation under the scene's own drive for rigid contact and
// against the rigid block on dem's Winkler base under the same drive for dem's overlap contact, both
// integrated independently (docs/validation.md, "Rocking under a ground motion").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analytic/rocking_oracle.hpp"
#include "analytic/winkler_frame.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "cases/ground_rocking_setup.hpp"
#include "cases/winkler_model.hpp"
#include "output/number_format.hpp"

namespace cairn::cases {

namespace {

void check_ground(const Scene& scene) { read_ground_setup(scene); }

/// why Housner's block does not model a rigid-contact run, or empty: it neither slides nor bounces.
/// A drive past μ·(g − f_z) slides a resting block (the Winkler base models that, Housner's
/// pivot does not); a rocking block can slide below it too, which this does not catch
std::string housner_unmodelled(const Scene& scene, const GroundSetup& s) {
    if (!s.stack.empty())
        return "a stack of " + std::to_string(s.stack.size()) +
               " blocks rocking on one another: no rigid-contact oracle models it (its blocks' motions are chaotic "
               "and each impact's loss is the engine's own); Housner's curve of the stack as one block is a guide";
    if (s.friction_demand <= scene.contact.friction) return "";
    char why[240];
    std::snprintf(why, sizeof why,
                  "the drive beats friction (|f_h|/(g − f_z) reaches %.3g > μ = %.3g): the block slides, which Housner's "
                  "pivot does not model",
                  s.friction_demand, scene.contact.friction);
    return why;
}

/// why the Winkler block does not model a penalty run, or empty
std::string penalty_unmodelled(const Scene& scene, ContactKind contact, const GroundSetup& s) {
    const std::string why = winkler_unmodelled(scene, contact, s.axis_block);
    if (!why.empty() || (s.columns == 1 && s.stack.empty())) return why;
    if (!s.stack.empty()) {
        const auto st = winkler_stack(scene, contact, s);
        int cells = 0;
        for (const auto& l : st.layers) cells += 2 * l.cells_across + 2 * l.cells_up;
        if (s.stack.size() > 16 || cells > oracle::WinklerStack::max_cells)
            return "a stack of " + std::to_string(s.stack.size()) + " blocks cut into " + std::to_string(cells) +
                   " contact cells: the Winkler stack models up to 16 blocks and " +
                   std::to_string(oracle::WinklerStack::max_cells) + " cells";
        return "";
    }
    const auto w = winkler_model(scene, contact, s.axis_block);
    const int cells = s.columns * (2 * w.cells_across + 2 * w.cells_up);
    if (s.columns > 8 || cells > oracle::WinklerFrame::max_cells)
        return "a frame of " + std::to_string(s.columns) + " columns under '" + s.beam + "' cut into " +
               std::to_string(cells) + " contact cells: the Winkler frame models up to 8 columns and " +
               std::to_string(oracle::WinklerFrame::max_cells) + " cells";
    return "";
}

/// what a rotation history did, read the same way from a run and from an oracle's curve
struct Response {
    double mark_time = NAN;    ///< s: |θ| first reaches the uplift mark
    double first_peak = NAN;   ///< rad: largest |θ| from there to the first return through 0 (NaN: none)
    double peak_end = NAN;     ///< s: that return
    double largest = 0.0;      ///< rad: largest |θ|
    double largest_time = 0.0; ///< s: when
    bool overturned = false;   ///< reached π/3, or ended beyond α
    double over_time = NAN;    ///< s: when |θ| first reached π/3 (the end when it only ended beyond α)
};

Response read_response(const metrics::Series& th, double mark, double alpha) {
    Response r;
    size_t i = 0;
    for (; i < th.t.size(); ++i)
        if (std::abs(th.y[i]) >= mark) break;
    for (size_t k = 0; k < th.t.size(); ++k) {
        if (std::abs(th.y[k]) > r.largest) r.largest = std::abs(th.y[k]), r.largest_time = th.t[k];
        if (std::isnan(r.over_time) && std::abs(th.y[k]) >= M_PI / 3.0) r.over_time = th.t[k];
    }
    r.overturned = r.largest >= M_PI / 3.0 || (!th.y.empty() && std::abs(th.y.back()) > alpha);
    if (r.overturned && std::isnan(r.over_time)) r.over_time = th.t.back();
    if (i == th.t.size()) return r;
    r.mark_time = i == 0 ? th.t[0]
                         : th.t[i - 1] + (th.t[i] - th.t[i - 1]) * (mark - std::abs(th.y[i - 1])) /
                                             (std::abs(th.y[i]) - std::abs(th.y[i - 1]));
    const double sign = th.y[i] > 0.0 ? 1.0 : -1.0;
    double peak = 0.0;
    size_t k = i;
    for (; k < th.t.size() && sign * th.y[k] > 0.0; ++k) peak = std::max(peak, std::abs(th.y[k]));
    if (k < th.t.size()) r.first_peak = peak, r.peak_end = th.t[k];   // a swing that returns
    return r;
}

/// the uplift mark: 5 % of the slenderness, above a penalty base's elastic tilt yet early in a rock
double uplift_mark(const GroundSetup& s) { return 0.05 * s.alpha; }

std::vector<double> ground_curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) {
    if (t.empty()) return {};
    const GroundSetup s = read_ground_setup(scene);
    if (contact.penalty) {
        if (!penalty_unmodelled(scene, contact, s).empty()) return {};
        return ground_winkler(scene, contact, s, t);
    }
    return ground_housner(scene, s, t, -1.0).theta;
}

/// the angle tolerance at a reference angle: 2 % plus 0.5 % of α (measured on the shipped pulses:
/// the rigid engines within 0.81 % of Housner, dem within 0.09 % of its Winkler base)
double angle_tolerance(const GroundSetup& s, double reference) { return 0.02 * std::abs(reference) + 0.005 * s.alpha; }

/// the time tolerance: 1 % of the block's time scale 1/p (measured within 0.73 ms on a 0.2 × 1.0 m
/// block, 1/p = 0.26 s)
double time_tolerance(const Scene& scene, const GroundSetup& s) { return 0.01 / ground_p(scene, s); }

/// How far the reference can be trusted: rocking is chaotic near a threshold, and the engines
/// differ from the oracles by about a 0.1 % change of the drive (measured: dem left its Winkler base
/// on a post under El Centro where that change does, and its verdict there flips with its step).
/// `horizon` is the first time the reference under the drive 0.1 % weaker or stronger leaves the
/// band of the tolerances (in angle, and in time by the time tolerance) around the reference;
/// `verdicts_agree` whether those two, and for Housner's block the impact ratios up to 1 (no loss:
/// a rigid engine's loss is its own), overturn as the reference does.
struct Trust {
    double horizon = std::numeric_limits<double>::infinity();   ///< s
    bool verdicts_agree = true;
};

/// the first time (s) `c` is nowhere within the angle tolerance of `ref` inside ±window of it; inf:
/// never. `ref` is read as the line through its samples, so the answer does not hinge on the output
/// interval: with rows 1 ms apart and a window of 0.83 ms (a 0.1 m tall block) a sampled window
/// held one row, and a curve shifted by a fraction of a row left the band on every steep stretch.
double leaves_band(const metrics::Series& ref, const std::vector<double>& c, const GroundSetup& s, double window) {
    const auto& t = ref.t;
    for (size_t i = 0, lo = 0; i < t.size(); ++i) {
        while (t[lo] < t[i] - window) ++lo;
        // the range of the line over [t_i − window, t_i + window]: its ends and the rows between
        const double y_before = metrics::interpolate(ref, t[i] - window), y_after = metrics::interpolate(ref, t[i] + window);
        double y_min = std::min(y_before, y_after), y_max = std::max(y_before, y_after);
        for (size_t j = lo; j < t.size() && t[j] <= t[i] + window; ++j) {
            y_min = std::min(y_min, ref.y[j]);
            y_max = std::max(y_max, ref.y[j]);
        }
        // the tolerance grows with |y| by less than the distance does, so the nearest y is the best
        const double y = std::clamp(c[i], y_min, y_max);
        if (std::abs(c[i] - y) > angle_tolerance(s, y)) return t[i];
    }
    return std::numeric_limits<double>::infinity();
}

Trust trust_of(const Scene& scene, ContactKind contact, const GroundSetup& s, const metrics::Series& ref, bool overturned) {
    const double mark = uplift_mark(s), window = time_tolerance(scene, s);
    Trust out;
    for (double k : {0.999, 1.001}) {
        GroundSetup p = s;
        p.scale = k;
        const auto c = contact.penalty ? ground_winkler(scene, contact, p, ref.t) : ground_housner(scene, p, ref.t, -1.0).theta;
        out.horizon = std::min(out.horizon, leaves_band(ref, c, s, window));
        out.verdicts_agree = out.verdicts_agree && read_response({ref.t, c}, mark, s.alpha).overturned == overturned;
    }
    if (!contact.penalty) {
        const double rh = ground_ratio(scene, s);
        for (double r : {0.5 * (1.0 + rh), 1.0})
            if (read_response({ref.t, ground_housner(scene, s, ref.t, r).theta}, mark, s.alpha).overturned != overturned)
                out.verdicts_agree = false;
    }
    return out;
}

/// the first sample time from `from` on at which the block's energy above rest (Housner's free
/// block, θ̇ by central differences of the curve) is below `level` (RockingOracle::energy's unit):
/// with the drive over, it can never again rise past the angle of that energy; inf: never
double calm_from(const metrics::Series& c, const oracle::RockingOracle& o, double from, double level) {
    for (size_t i = 1; i + 1 < c.t.size(); ++i) {
        if (c.t[i] < from) continue;
        const double w = (c.y[i + 1] - c.y[i - 1]) / (c.t[i + 1] - c.t[i - 1]);
        if (o.energy(c.y[i], w) < level) return c.t[i];
    }
    return std::numeric_limits<double>::infinity();
}

/// `judged` when it is settled by time `decided` (s), before the reference's horizon, or the
/// reference has no horizon within the run; else shown
metrics::Metric if_trusted(metrics::Metric judged, double decided, const Trust& trust) {
    if (decided < trust.horizon || !std::isfinite(trust.horizon)) return judged;
    char why[240];
    std::snprintf(why, sizeof why,
                  "; not judged: from %.4g s on, a 0.1 %% change of the drive moves the reference past the tolerance "
                  "(chaotic rocking)", trust.horizon);
    metrics::Metric shown = metrics::info(judged.name, judged.unit, judged.value, judged.reference, judged.basis + why);
    shown.measured = judged.measured;
    return shown;
}

/// the frame's reference, named with its numbers
std::string frame_label(const Scene& scene, const GroundSetup& s) {
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "the rigid frame of Makris & Vassiliou (2013): %d columns under '%s', γ = m_beam/(N m_column) = %.4g, "
                  "p̂ = p·√((1 + 2γ)/(1 + 3γ)) = %.5g 1/s, impact ratio (1 − 1.5 sin²α + 3γ cos 2α)/(1 + 3γ) = %.5g",
                  s.columns, s.beam.c_str(), s.gamma, ground_p(scene, s), ground_ratio(scene, s));
    return buf;
}

CaseAnalysis analyse_ground(const Scene& scene, const std::vector<Sample>& samples, ContactKind contact) {
    using namespace metrics;
    const GroundSetup s = read_ground_setup(scene);
    CaseAnalysis out;
    out.quantity = "rocking angle θ of A about its bottom edge, rad";
    out.measured = angle_series(samples, s.free, s.axis);
    const auto& t = out.measured.t;
    const double mark = uplift_mark(s);
    const Response run = read_response(out.measured, mark, s.alpha);
    if (std::isfinite(run.mark_time)) out.event_time = run.mark_time, out.has_event = true;

    const std::string unmodelled = contact.penalty ? penalty_unmodelled(scene, contact, s) : housner_unmodelled(scene, s);
    if (!unmodelled.empty()) {
        out.analytic_key = "Housner";
        if (!s.stack.empty()) {
            // the stack rocking as one block: how a column of equal drums first lifts
            const StackMonolith one = stack_monolith(scene, s);
            out.analytic = stack_housner(scene, s, t).theta;
            out.analytic_label = "Housner's rigid block of the stack as one (half-width " + message_number(one.b) +
                                 " m, centre of mass " + message_number(one.h) + " m up) under the same drive (guide only)";
        } else {
            out.analytic = ground_housner(scene, s, t, -1.0).theta;
            out.analytic_label = (s.columns > 1 ? frame_label(scene, s) : "Housner's rigid block under the same drive") + " (guide only)";
        }
        const Response ref = read_response({t, out.analytic}, mark, s.alpha);
        out.metrics.push_back(not_comparable("largest rotation", "rad", run.largest, ref.largest, unmodelled));
        return out;
    }
    const bool winkler = contact.penalty;
    if (winkler) {
        out.analytic = ground_winkler(scene, contact, s, t);
        out.analytic_key = !s.stack.empty() ? "Winkler stack" : s.columns > 1 ? "Winkler frame" : "Winkler base";
        out.analytic_label =
            !s.stack.empty()
                ? "the stack's rigid blocks on no-tension Winkler bed joints of modulus kn under the same drive (dem's "
                  "shear springs and dashpots per sub-contact), integrated independently"
            : s.columns > 1 ? "the frame's rigid columns and beam on no-tension Winkler joints of modulus kn (base and "
                              "column tops) under the same drive (dem's shear springs and dashpots per sub-contact), "
                              "integrated independently"
                          : "rigid block on a no-tension Winkler base of modulus kn under the same drive (dem's shear "
                            "springs and dashpots per sub-contact), integrated independently";
    } else {
        out.analytic = ground_housner(scene, s, t, -1.0).theta;
        out.analytic_key = "Housner";
        out.analytic_label = s.columns > 1 ? frame_label(scene, s)
                                           : "Housner's rigid block under the scene's drive, impact ratio 1 − 1.5 sin²α";
    }
    const Series ref_curve{t, out.analytic};
    const Response ref = read_response(ref_curve, mark, s.alpha);
    const Trust trust = trust_of(scene, contact, s, ref_curve, ref.overturned);
    // a deformable block far softer than a rigid one against its joints rocks as a flexible body
    std::string flexible = flexible_block_reason(scene, scene.reference->block, contact.deformable, kRigidUnderDrive);
    if ((s.columns > 1 || !s.stack.empty()) && contact.deformable)   // a frame or a stack: its softest member
        for (size_t b = 0; b < scene.blocks.size() && flexible.empty(); ++b)
            if (!scene.blocks[b].fixed) flexible = flexible_block_reason(scene, int(b), true, kFrameRigidUnderDrive);
    if (!flexible.empty()) {
        out.metrics.push_back(info("largest rotation", "rad", run.largest, ref.largest, flexible));
        return out;
    }
    const char* slop = " (rigid-contact engines: their step and contact slop)";
    const std::string winkler_model = std::string(!s.stack.empty() ? "the stack on Winkler joints"
                                                  : s.columns > 1  ? "the frame on Winkler joints"
                                                                   : "the Winkler base") +
                                      " (dem's contact law, integrated independently)";
    const std::string model = winkler         ? winkler_model
                              : s.columns > 1 ? std::string("the rigid frame of Makris & Vassiliou") + slop
                                              : std::string("Housner's rigid block") + slop;
    const double t_tol = time_tolerance(scene, s);
    char basis[300];
    std::snprintf(basis, sizeof basis, "%s; 2 %% plus 0.5 %% of α = %.3g rad", model.c_str(), 0.005 * s.alpha);
    auto angle = [&](const char* name, double value, double reference) {
        return absolute(name, "rad", value, reference, angle_tolerance(s, reference), basis);
    };
    const oracle::RockingOracle free_block = ground_oracle(scene, s);
    const double hill = free_block.energy(s.alpha, 0.0);
    // the verdict is settled when it overturns, or once the drive is over and the energy is below
    // the hill (a 5 % margin: a Winkler base stores a little more than the rigid block's energy);
    // the largest rotation once the energy cannot bring it back
    const double verdict_time =
        ref.overturned ? ref.over_time : calm_from(ref_curve, free_block, s.end, 0.95 * hill);
    const double largest_time =
        calm_from(ref_curve, free_block, std::max(s.end, ref.largest_time), free_block.energy(ref.largest, 0.0));
    if (!std::isfinite(ref.mark_time)) {
        // it stays on its base: a rigid block does not turn; a Winkler base tilts it elastically
        out.metrics.push_back(if_trusted(angle("largest rotation", run.largest, ref.largest), largest_time, trust));
        return out;
    }
    char t_basis[300];
    std::snprintf(t_basis, sizeof t_basis, "%s; 1 %% of the time scale 1/p = %.3g s", model.c_str(), t_tol / 0.01);
    const char* uplift = "uplift (|θ| = 5 % of α)";
    if (std::isfinite(run.mark_time))
        out.metrics.push_back(if_trusted(absolute(uplift, "s", run.mark_time, ref.mark_time, t_tol, t_basis), ref.mark_time, trust));
    else
        out.metrics.push_back(if_trusted(missing(uplift, "s", ref.mark_time, t_tol, Check::absolute,
                                                 "the block never turned past 5 % of its slenderness"),
                                         ref.mark_time, trust));
    if (std::isfinite(ref.first_peak)) {
        if (std::isfinite(run.first_peak))
            out.metrics.push_back(if_trusted(angle("first peak", run.first_peak, ref.first_peak), ref.peak_end, trust));
        else
            out.metrics.push_back(if_trusted(missing("first peak", "rad", ref.first_peak, angle_tolerance(s, ref.first_peak),
                                                     Check::absolute, "the run's first swing did not come back"),
                                             ref.peak_end, trust));
    }
    const double said = ref.overturned ? 1.0 : 0.0, did = run.overturned ? 1.0 : 0.0;
    const char* rule = "overturned: |θ| reached π/3, or ended beyond α";
    const char* as = winkler ? (!s.stack.empty() ? "as the stack on Winkler joints; "
                                : s.columns > 1    ? "as the frame on Winkler joints; "
                                                   : "as the Winkler base; ")
                       : s.columns > 1 ? "as the rigid frame; "
                                       : "as Housner's block; ";
    const std::string verdict_basis = as + std::string(rule);
    if (!winkler && scene.contact.restitution > 0.0)
        out.metrics.push_back(info("overturns (1 yes, 0 no)", "", did, said,
                                   "the scene's restitution bounces the rigid engines' impacts; Housner's do not"));
    else if (!trust.verdicts_agree)
        out.metrics.push_back(info("overturns (1 yes, 0 no)", "", did, said,
                                   verdict_basis + "; not judged: a 0.1 % change of the drive" +
                                       (winkler ? "" : " or a smaller impact loss") + " changes the reference's verdict"));
    else
        out.metrics.push_back(if_trusted(absolute("overturns (1 yes, 0 no)", "", did, said, 0.0, verdict_basis),
                                         verdict_time, trust));
    if (winkler && !ref.overturned)
        out.metrics.push_back(if_trusted(angle("largest rotation", run.largest, ref.largest), largest_time, trust));
    else
        out.metrics.push_back(info("largest rotation", "rad", run.largest, ref.largest,
                                   winkler ? "past overturning" : "over the run, through impacts whose loss is each engine's own"));
    return out;
}

// the oracles work with gravity along −z: a scene in any other world is turned whole onto it, its
// run with it (every metric is an angle, a time or a verdict, the same in both)
CaseAnalysis analyse_any_world(const Scene& scene, const std::vector<Sample>& samples, ContactKind contact) {
    const Quat r = gravity_down(scene);
    return analyse_ground(turned_scene(scene, r), turned_samples(samples, r), contact);
}

std::vector<double> curve_any_world(const Scene& scene, ContactKind contact, const std::vector<double>& t) {
    return ground_curve(turned_scene(scene, gravity_down(scene)), contact, t);
}

}  // namespace

// kind "ground_rocking": rigid contact against Housner, dem's overlap contact against its Winkler base
static const CaseKind& ground_rocking_kind() {
    static const FunctionKind k("ground_rocking", {}, analyse_any_world, curve_any_world, rigid_contact_only,
                                "uplift (|θ| = 5 % of α)",
                                [](const Scene& s) { check_ground(turned_scene(s, gravity_down(s))); });
    return k;
}

namespace {
const KindRegistration ground_rocking_registered(ground_rocking_kind);
}  // namespace

}  // namespace cairn::cases
