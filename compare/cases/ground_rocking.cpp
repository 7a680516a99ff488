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
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "cases/winkler_model.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"

namespace cairn::cases {

namespace {

const char* const kKind = "ground_rocking";

/// what the oracles need of the scene
struct Setup {
    int free = 0;                        ///< the block among the free blocks (Sample::blocks)
    Vec3 dir = Vec3::UnitX();            ///< unit, world, horizontal: the drive's first push; θ > 0 moves the centre this way
    Vec3 axis = Vec3::UnitY();           ///< z × dir, world: θ is a turn about it
    Vec3 axis_block = Vec3::UnitY();     ///< the same in the block frame, along a block axis
    std::function<Vec3(double)> drive;   ///< the block's loads per unit mass at t (m/s², world)
    std::vector<double> breaks;          ///< s, ascending: where the drive kinks or jumps
    double end = 0.0;                    ///< s: the drive is zero from here on
    double alpha = 0.0;                  ///< slenderness atan(b/h) across the axis, rad
    double scale = 1.0;                  ///< the oracles' horizontal drive is the scene's times this
};

Error refuse(const Scene& scene, const std::string& what) {
    return Error(scene.source + ": " + what + " (a " + kKind + " reference)");
}

/// the block's loads per unit mass, their breaks and end; each must act at the centre of mass
void read_drive(const Scene& scene, const BlockDef& d, Setup& out) {
    const int a = scene.reference->block;
    const double m = block_mass(scene, a);
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const auto& c : d.corners) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
    const Vec3 centre = mass_properties(d.corners, 1.0).centre;
    bool lasting = false;
    for (const auto& l : scene.loads) {
        if (l.block != a) continue;
        if (!l.body && (l.point - centre).norm() > 1e-9 * (hi - lo).maxCoeff())
            throw refuse(scene, "a load on block '" + d.name +
                                    "' acts off its centre of mass: the oracles drive the block at its centre (a "
                                    "[ground_motion], or loads with point = \"centre\")");
        out.breaks.push_back(l.start);
        if (l.ramp > 0.0) out.breaks.push_back(l.start + l.ramp);
        if (l.history) {
            for (double t : l.history->time) out.breaks.push_back(l.start + t);
            out.end = std::max(out.end, l.start + l.history->time.back());
        } else {
            lasting = true;
        }
    }
    if (lasting) out.end = std::max(out.end, scene.run.duration);
    std::sort(out.breaks.begin(), out.breaks.end());
    out.breaks.erase(std::unique(out.breaks.begin(), out.breaks.end()), out.breaks.end());
    out.drive = [&scene, a, m](double t) {
        Vec3 f = Vec3::Zero();
        for (const auto& l : scene.loads)
            if (l.block == a) f += l.factor(t) * l.force;
        return Vec3(f / m);
    };
}

/// the one horizontal direction of the drive (it is linear between its breaks, so sampling them
/// and their midpoints sees all of it); throws when it has none, turns, or lifts the block off
void read_direction(const Scene& scene, const BlockDef& d, Setup& out) {
    std::vector<double> at = out.breaks;
    for (size_t i = 0; i + 1 < out.breaks.size(); ++i) at.push_back(0.5 * (out.breaks[i] + out.breaks[i + 1]));
    Vec3 largest = Vec3::Zero();
    for (double t : at) {
        const Vec3 f = out.drive(t), h(f.x(), f.y(), 0.0);
        if (h.norm() > largest.norm()) largest = h;
        if (gravity(scene) - f.z() <= 0.0) {
            char buf[160];
            std::snprintf(buf, sizeof buf, "the drive's vertical part lifts the block off at t = %.6g s", t);
            throw refuse(scene, buf);
        }
    }
    if (!(largest.norm() > 0.0)) throw refuse(scene, "block '" + d.name + "' has no horizontal drive to rock it");
    out.dir = largest.normalized();
    // θ > 0 the way the drive first pushes (its first sample past 1e-6 of the largest)
    for (double t : out.breaks) {
        const Vec3 f = out.drive(t), h(f.x(), f.y(), 0.0);
        if (h.norm() > 1e-6 * largest.norm()) {
            if (h.dot(out.dir) < 0.0) out.dir = -out.dir;
            break;
        }
    }
    for (double t : at) {
        const Vec3 f = out.drive(t), h(f.x(), f.y(), 0.0);
        if ((h - h.dot(out.dir) * out.dir).norm() > 1e-6 * largest.norm())
            throw refuse(scene, "the horizontal drive on block '" + d.name +
                                    "' turns in the plane: Housner's oracle rocks in one plane, along one direction");
    }
    out.axis = Vec3::UnitZ().cross(out.dir);
    // 1e-3 rad: a direction written to four decimals in degrees
    const Vec3 bx = d.orientation * Vec3::UnitX(), by = d.orientation * Vec3::UnitY();
    if (std::abs(out.dir.dot(bx)) >= std::cos(1e-3)) {
        out.axis_block = Vec3::UnitY() * (out.dir.dot(bx) > 0.0 ? 1.0 : -1.0);
    } else if (std::abs(out.dir.dot(by)) >= std::cos(1e-3)) {
        out.axis_block = -Vec3::UnitX() * (out.dir.dot(by) > 0.0 ? 1.0 : -1.0);
    } else {
        char buf[200];
        std::snprintf(buf, sizeof buf, "the horizontal drive, a ground acceleration along (%.4g, %.4g), is not along a side of block '%s'",
                      -out.dir.x(), -out.dir.y(), d.name.c_str());
        throw refuse(scene, std::string(buf) + ": the block would rock on a corner, which the plane oracles do not model");
    }
}

/// the block stands wholly on the top of one fixed block: its four lowest corners inside that top
/// (in the support's frame) and at its height within 1 % of the block's height (a placing gap);
/// on a narrower support it would rock about the support's edges, not its own
void require_support(const Scene& scene, const BlockDef& d) {
    std::array<Vec3, 8> world;
    for (size_t i = 0; i < 8; ++i) world[i] = d.position + d.orientation * d.corners[i];
    std::sort(world.begin(), world.end(), [](const Vec3& a, const Vec3& b) { return a.z() < b.z(); });
    const double bottom = world[0].z(), height = world[7].z() - world[0].z();
    for (const auto& b : scene.blocks) {
        if (!b.fixed) continue;
        Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
        double top = -1e300;
        for (const auto& c : b.corners) {
            lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
            top = std::max(top, (b.position + b.orientation * c).z());
        }
        const double eps = 1e-9 * (hi - lo).maxCoeff();
        bool inside = std::abs(top - bottom) <= 0.01 * height;
        for (size_t i = 0; i < 4 && inside; ++i) {
            const Vec3 l = b.orientation.conjugate() * (world[i] - b.position);
            inside = l.x() >= lo.x() - eps && l.x() <= hi.x() + eps && l.y() >= lo.y() - eps && l.y() <= hi.y() + eps;
        }
        if (inside) return;
    }
    throw refuse(scene, "block '" + d.name +
                            "' does not stand wholly on the top of a fixed block: it would rock about the support's edges, "
                            "not its own");
}

/// the scene as the oracles see it; throws cairn::Error naming what they cannot model
Setup read_setup(const Scene& scene) {
    require_horizontal_base(scene, kKind);
    const int a = scene.reference->block;
    const BlockDef& d = scene.blocks.at(size_t(a));
    for (const auto& b : scene.blocks)
        if (!b.fixed && b.name != d.name)
            throw refuse(scene, "blocks." + b.name + ": the oracles model block '" + d.name + "' alone, and the scene has another free block");
    if ((d.orientation * Vec3::UnitZ()).z() < std::cos(1e-3))
        throw refuse(scene, "blocks." + d.name + ".orientation: the block must stand upright");
    if (d.velocity.norm() > 0.0 || d.angular_velocity.norm() > 0.0)
        throw refuse(scene, "blocks." + d.name + ": the block must start at rest");
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const auto& c : d.corners) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
    for (const auto& c : d.corners)
        for (int k = 0; k < 3; ++k)
            if (std::min(std::abs(c[k] - lo[k]), std::abs(c[k] - hi[k])) > 1e-9 * (hi - lo).maxCoeff())
                throw refuse(scene, "blocks." + d.name + ": the block must be rectangular (its corners on a box in its frame)");
    require_support(scene, d);
    Setup out;
    out.free = free_index(scene, a);
    read_drive(scene, d, out);
    read_direction(scene, d, out);
    out.alpha = housner_block(scene, out.axis_block).alpha();
    return out;
}

void check_ground(const Scene& scene) { read_setup(scene); }

/// the drive as Housner's oracle takes it: the ground's acceleration along dir and upwards
oracle::BaseMotion base_motion(const Setup& s) {
    oracle::BaseMotion m;
    const auto drive = s.drive;
    const Vec3 dir = s.dir;
    const double k = s.scale;
    m.horizontal = [drive, dir, k](double t) { return -k * drive(t).dot(dir); };
    m.vertical = [drive](double t) { return -drive(t).z(); };
    m.end = s.end;
    m.breaks = s.breaks;
    return m;
}

/// Housner's block under the scene's drive at the times t, with impact ratio r (< 0: Housner's)
oracle::RockingResult housner_run(const Scene& scene, const Setup& s, const std::vector<double>& t, double r) {
    const auto hb = housner_block(scene, s.axis_block);
    oracle::RockingOptions o;
    o.restitution = r;
    o.duration = t.empty() ? scene.run.duration : t.back();
    o.output_times = t;
    return oracle::RockingOracle(hb.b, hb.h, gravity(scene)).run(base_motion(s), o);
}

/// the Winkler block of dem's contact under the same drive, θ at the times t
std::vector<double> winkler_run(const Scene& scene, ContactKind contact, const Setup& s, const std::vector<double>& t) {
    auto w = winkler_model(scene, contact, s.axis_block);
    // 100 RK4 steps per contact period, not the oracle's 400: its error, of order (2π/100)⁴ of a
    // period's motion, stays far below the 0.1 % change of the drive the horizon probes (measured:
    // the judged numbers the same to six digits, a 30 s record's analysis 2.3 times faster)
    w.steps_per_period = 100.0;
    const auto drive = s.drive;
    const Vec3 dir = s.dir;
    const double k = s.scale;
    w.drive = [drive, dir, k](double x) {
        const Vec3 f = drive(x);
        return std::array<double, 2>{k * f.dot(dir), f.z()};
    };
    const auto tr = w.rest(t.back() + 1e-9, std::min(1e-3, t.size() > 1 ? t[1] - t[0] : 1e-3));
    const metrics::Series theta{tr.t, tr.theta};
    std::vector<double> out;
    out.reserve(t.size());
    for (double x : t) out.push_back(metrics::interpolate(theta, x));
    return out;
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
double uplift_mark(const Setup& s) { return 0.05 * s.alpha; }

std::vector<double> ground_curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) {
    if (t.empty()) return {};
    const Setup s = read_setup(scene);
    if (contact.penalty) {
        if (!winkler_unmodelled(scene, contact, s.axis_block).empty()) return {};
        return winkler_run(scene, contact, s, t);
    }
    return housner_run(scene, s, t, -1.0).theta;
}

/// the angle tolerance at a reference angle: 2 % plus 0.5 % of α (measured within 0.4 %, rigid
/// engines against Housner and dem against its Winkler base)
double angle_tolerance(const Setup& s, double reference) { return 0.02 * std::abs(reference) + 0.005 * s.alpha; }

/// the time tolerance: 1 % of the block's time scale 1/p (measured within 0.3 ms on a 0.2 × 1.0 m
/// block, 1/p = 0.26 s)
double time_tolerance(const Scene& scene, const Setup& s) { return 0.01 / housner_block(scene, s.axis_block).p(); }

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

/// the first time (s) `c` is nowhere within `tol` of `ref` inside ±window of it; inf: never
double leaves_band(const metrics::Series& ref, const std::vector<double>& c, const Setup& s, double window) {
    const auto& t = ref.t;
    for (size_t i = 0, lo = 0; i < t.size(); ++i) {
        while (t[lo] < t[i] - window) ++lo;
        bool near = false;
        for (size_t j = lo; j < t.size() && t[j] <= t[i] + window && !near; ++j)
            near = std::abs(c[i] - ref.y[j]) <= angle_tolerance(s, ref.y[j]);
        if (!near) return t[i];
    }
    return std::numeric_limits<double>::infinity();
}

Trust trust_of(const Scene& scene, ContactKind contact, const Setup& s, const metrics::Series& ref, bool overturned) {
    const double mark = uplift_mark(s), window = time_tolerance(scene, s);
    Trust out;
    for (double k : {0.999, 1.001}) {
        Setup p = s;
        p.scale = k;
        const auto c = contact.penalty ? winkler_run(scene, contact, p, ref.t) : housner_run(scene, p, ref.t, -1.0).theta;
        out.horizon = std::min(out.horizon, leaves_band(ref, c, s, window));
        out.verdicts_agree = out.verdicts_agree && read_response({ref.t, c}, mark, s.alpha).overturned == overturned;
    }
    if (!contact.penalty) {
        const double rh = housner_block(scene, s.axis_block).velocity_ratio();
        for (double r : {0.5 * (1.0 + rh), 1.0})
            if (read_response({ref.t, housner_run(scene, s, ref.t, r).theta}, mark, s.alpha).overturned != overturned)
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

CaseAnalysis analyse_ground(const Scene& scene, const std::vector<Sample>& samples, ContactKind contact) {
    using namespace metrics;
    const Setup s = read_setup(scene);
    CaseAnalysis out;
    out.quantity = "rocking angle θ of A about its bottom edge, rad";
    out.measured = angle_series(samples, s.free, s.axis);
    const auto& t = out.measured.t;
    const double mark = uplift_mark(s);
    const Response run = read_response(out.measured, mark, s.alpha);
    if (std::isfinite(run.mark_time)) out.event_time = run.mark_time, out.has_event = true;

    const std::string unmodelled = contact.penalty ? winkler_unmodelled(scene, contact, s.axis_block) : "";
    if (!unmodelled.empty()) {
        out.analytic = housner_run(scene, s, t, -1.0).theta;
        out.analytic_key = "Housner";
        out.analytic_label = "Housner's rigid block under the same drive (guide only)";
        const Response ref = read_response({t, out.analytic}, mark, s.alpha);
        out.metrics.push_back(not_comparable("largest rotation", "rad", run.largest, ref.largest, unmodelled));
        return out;
    }
    const bool winkler = contact.penalty;
    if (winkler) {
        out.analytic = winkler_run(scene, contact, s, t);
        out.analytic_key = "Winkler base";
        out.analytic_label = "rigid block on a no-tension Winkler base of modulus kn under the same drive (dem's shear "
                             "springs and dashpots per sub-contact), integrated independently";
    } else {
        out.analytic = housner_run(scene, s, t, -1.0).theta;
        out.analytic_key = "Housner";
        out.analytic_label = "Housner's rigid block under the scene's drive, impact ratio 1 − 1.5 sin²α";
    }
    const Series ref_curve{t, out.analytic};
    const Response ref = read_response(ref_curve, mark, s.alpha);
    const Trust trust = trust_of(scene, contact, s, ref_curve, ref.overturned);
    const std::string model = winkler ? "the Winkler base (dem's contact law, integrated independently)"
                                      : "Housner's rigid block (rigid-contact engines: their step and contact slop)";
    const double t_tol = time_tolerance(scene, s);
    char basis[300];
    std::snprintf(basis, sizeof basis, "%s; 2 %% plus 0.5 %% of α = %.3g rad", model.c_str(), 0.005 * s.alpha);
    auto angle = [&](const char* name, double value, double reference) {
        return absolute(name, "rad", value, reference, angle_tolerance(s, reference), basis);
    };
    const auto hb = housner_block(scene, s.axis_block);
    const oracle::RockingOracle free_block(hb.b, hb.h, hb.g);
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
    const std::string verdict_basis = (winkler ? "as the Winkler base; " : "as Housner's block; ") + std::string(rule);
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

}  // namespace

// kind "ground_rocking": rigid contact against Housner, dem's overlap contact against its Winkler base
static const CaseKind& ground_rocking_kind() {
    static const FunctionKind k(kKind, {}, analyse_ground, ground_curve, rigid_contact_only, "uplift (|θ| = 5 % of α)",
                                check_ground);
    return k;
}

namespace {
const KindRegistration ground_rocking_registered(ground_rocking_kind);
}  // namespace

}  // namespace cairn::cases
