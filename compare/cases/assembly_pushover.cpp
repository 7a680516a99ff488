// a pushover of any block assembly against its rigid-block limit analysis
#include "cases/assembly_pushover.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "analytic/block_interfaces.hpp"
#include "analytic/block_limit_analysis.hpp"
#include "cases/case_util.hpp"
#include "cases/scene_stack.hpp"
#include "cases/structure_kinds.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "output/number_format.hpp"
#include "scene/scene_io.hpp"

namespace cairn::cases {

namespace {

/// friction at which the LP's joints hardly slide (a sliding joint dilates by μ times its slip)
constexpr double kNoSlip = 100.0;
constexpr double kSlipShare = 0.05;   // a joint slipping at 5 % of the mechanism's speed: sliding takes part
constexpr double kInset = 1e-3;       // m: how far inside an edge a rigid engine's contact hinges (Bullet's
                                      // margin rounds every box edge by 1 mm; ODE's and MuJoCo's contacts are soft)

std::string head(const Scene& scene) { return scene.source + ": reference.kind = \"pushover\": "; }

/// the sign of the record's largest excursion: a ramp written negative pushes against `direction`
double record_sign(const Scene& scene) {
    double lo = 0.0, hi = 0.0;
    for (double a : scene.ground_motion->components.front().acceleration.value) lo = std::min(lo, a), hi = std::max(hi, a);
    return hi >= -lo ? 1.0 : -1.0;
}

/// the largest relative slip at a joint's contact points against the largest contact-point speed
double slip_share(const std::vector<oracle::LimitBlock>& blocks, const std::vector<oracle::LimitTwist>& twist) {
    std::vector<Corners> corners;
    std::vector<bool> fixed;
    Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
    for (const auto& b : blocks) {
        corners.push_back(b.corners);
        fixed.push_back(b.fixed);
        for (const Vec3& p : b.corners) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    }
    auto speed = [&](int i, const Vec3& p) {
        return Vec3(twist[size_t(i)].velocity + twist[size_t(i)].angular.cross(p - blocks[size_t(i)].centre));
    };
    double slip = 0.0, fastest = 0.0;
    // the joints the analysis found: within 1e-5 of the assembly's size (block_limit_analysis.cpp)
    for (const auto& j : oracle::find_interfaces(corners, fixed, 1e-5 * (hi - lo).norm()))
        for (const Vec3& p : j.polygon) {
            const Vec3 rel = speed(j.first, p) - speed(j.second, p);
            fastest = std::max(fastest, rel.norm());
            slip = std::max(slip, (rel - rel.dot(j.normal) * j.normal).norm());
        }
    return fastest > 0.0 ? slip / fastest : 0.0;
}

/// refuses a record that falls back within the run: the pushover reads a/g when a block turns as
/// the multiplier that turned it, which only a load that grows and then stays holds (a pulse that
/// has ended has a/g = 0 when its blocks fall); it may start later (`start`) and level off
void require_ramp(const Scene& scene) {
    const GroundMotion& gm = *scene.ground_motion;
    const TimeSeries& a = gm.components.front().acceleration;
    const double sign = record_sign(scene), T = scene.run.duration;
    // the record's own samples within the run, its ends and the run's end (zero outside the record)
    std::vector<double> at = {0.0, T};
    for (double t : a.time) {
        const double eps = 1e-12 * (1.0 + std::abs(t));   // either side of a sample: a step there
        for (double s : {gm.start + t - eps, gm.start + t, gm.start + t + eps})
            if (s >= 0.0 && s <= T) at.push_back(s);
    }
    std::sort(at.begin(), at.end());
    double peak = 0.0;
    for (double t : at) peak = std::max(peak, std::abs(a.at(t - gm.start)));
    const double g = scene.gravity.norm();
    double last = 0.0, last_t = 0.0;
    for (double t : at) {
        const double v = sign * a.at(t - gm.start);
        // 1e-9 of the peak: a record written to nine digits
        if (v < last - 1e-9 * peak || v < -1e-9 * peak)
            throw Error(head(scene) + "[ground_motion]: the pushover needs a ramp, a record that grows and never falls "
                                      "back within the run, and a/g falls from " + message_number(sign * last / g) +
                        " at t = " + message_number(last_t) + " s to " + message_number(sign * v / g) + " at t = " +
                        message_number(t) + " s (a pulse or a record: reference.kind = \"ground_rocking\" for a block, "
                        "a stack or a frame, or no [reference] to compare the engines with each other)");
        if (v > last) last = v, last_t = t;
    }
}

}  // namespace

void require_pushover_drive(const Scene& scene) {
    if (!scene.ground_motion || scene.ground_motion->components.size() != 1)
        throw Error(head(scene) + "[ground_motion]: one record along a horizontal direction is needed");
    const Vec3 up = -scene.gravity.normalized(), dir = scene.ground_motion->components.front().direction;
    if ((dir - dir.dot(up) * up).norm() < 1 - 1e-6)
        throw Error(head(scene) + "ground_motion.direction must be horizontal (the pushover's live load)");
    for (const auto& l : scene.loads)
        if (!(l.body && l.history))
            throw Error(head(scene) + "[loads]: a load on block '" + scene.blocks.at(size_t(l.block)).name +
                        "' is not modelled by the pushover reference (only its ground motion is)");
    for (const auto& b : scene.blocks)
        if (!b.fixed && (b.velocity.norm() > 0.0 || b.angular_velocity.norm() > 0.0))
            throw Error(head(scene) + "blocks." + b.name + ".velocity/angular_velocity: the pushover starts at rest");
    require_ramp(scene);
}

namespace {

/// the limit analyses of a scene (three linear programmes, seconds for a wall of hundreds of
/// bricks), remembered by the scene's whole content for the analyses of its other variants
class AnalysisMemo {
public:
    std::optional<AssemblyPushover> find(const std::string& key) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& [k, v] : entries_)
            if (k == key) return v;
        return std::nullopt;
    }
    void keep(const std::string& key, const AssemblyPushover& value) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (entries_.size() >= 4) entries_.erase(entries_.begin());   // bounded: a few scenes at a time
        entries_.emplace_back(key, value);
    }

private:
    std::mutex mutex_;
    std::vector<std::pair<std::string, AssemblyPushover>> entries_;
};

AssemblyPushover analyse_limits(const Scene& scene);

}  // namespace

AssemblyPushover assembly_pushover(const Scene& scene) {
    require_pushover_drive(scene);
    static AnalysisMemo memo;
    const std::string key = scene_to_json(scene).dump();
    if (auto known = memo.find(key)) return *known;
    AssemblyPushover r = analyse_limits(scene);
    memo.keep(key, r);
    return r;
}

namespace {

AssemblyPushover analyse_limits(const Scene& scene) {
    const Vec3 dir = scene.ground_motion->components.front().direction;
    AssemblyPushover r;
    r.record_sign = record_sign(scene);
    const Vec3 live = -r.record_sign * gravity(scene) * dir;   // −m·a_g per unit a/g
    const auto blocks = oracle::limit_blocks(scene);
    auto la = oracle::collapse_multiplier(blocks, scene.gravity, live, scene.contact.friction);
    r.interfaces = la.interfaces;
    // where several mechanisms give the same λ, the LP's duals may return one whose joints slide,
    // and which one hangs on the blocks' order (a column pushed along its diagonal, its blocks
    // renamed: every verdict went "not judged"). Where joints that hardly slide (μ = kNoSlip) give
    // the same λ, a mechanism without sliding collapses it too, and that one is taken
    if (la.stands_at_zero && std::isfinite(la.lambda) && scene.contact.friction < kNoSlip) {
        const auto rocking = oracle::collapse_multiplier(blocks, scene.gravity, live, kNoSlip);
        if (std::isfinite(rocking.lambda) && !rocking.mechanism.empty() && rocking.lambda <= la.lambda * (1 + 1e-9))
            la.mechanism = rocking.mechanism;
    }
    if (!la.stands_at_zero)
        throw Error(head(scene) + "blocks: no statically admissible state under gravity alone (rigid-block limit "
                    "analysis, " + std::to_string(la.interfaces) + " joints): the assembly does not stand, so no pushover");
    if (!std::isfinite(la.lambda) || la.mechanism.empty())
        throw Error(head(scene) + "[ground_motion]: limit analysis finds no mechanism (the fixed blocks carry the live "
                    "load without limit)");
    r.lambda = la.lambda;

    // the mechanism as one degree of freedom q (m): M q̈ = P·(λ(t) − λc)
    double gravity_power = 0.0, size = 0.0;
    for (size_t i = 0; i < blocks.size(); ++i) {
        if (blocks[i].fixed) continue;
        const auto& w = la.mechanism[i];
        const MassProperties unit = mass_properties(blocks[i].corners, 1.0);   // density 1: scale by the mass
        const Mat3 inertia = unit.inertia * (blocks[i].mass / unit.volume);
        size = std::max(size, shortest_edge(blocks[i].corners));
        r.mass += blocks[i].mass * w.velocity.squaredNorm() + w.angular.dot(inertia * w.angular);
        r.push += blocks[i].mass * live.dot(w.velocity);
        gravity_power += blocks[i].mass * scene.gravity.dot(w.velocity);
        r.turn = std::max(r.turn, w.angular.norm());
    }
    if (r.push < 0.0) r.push = -r.push, gravity_power = -gravity_power;
    // at λc the mechanism's power vanishes: gravity's work balances the live load's
    if (!(r.push > 0.0) || std::abs(gravity_power + r.lambda * r.push) > 1e-6 * r.push * std::max(1.0, r.lambda))
        throw Error(head(scene) + "blocks: the limit analysis's mechanism does not balance its work (solver trouble); "
                    "not judged");
    r.slip_share = slip_share(blocks, la.mechanism);
    // a mechanism in which no block turns (the fastest less than a thousandth of its speed over its
    // size) only slides: shown, not judged, whichever of the LP's equal mechanisms its duals give
    if (r.turn * size < 1e-3) r.slip_share = 1.0;
    // friction the static state leans on: with 10 % less of it λ falls (a brick hung on its head
    // joint by friction, which Coulomb's joints, slipping without dilating, need not give)
    r.friction_binds =
        oracle::collapse_multiplier(blocks, scene.gravity, live, 0.9 * scene.contact.friction).lambda < (1 - 1e-3) * r.lambda;
    // NaN: with its joints inset the assembly cannot stand at all, so nothing bounds it from below
    const double inset = oracle::collapse_multiplier(blocks, scene.gravity, live, scene.contact.friction, kInset).lambda;
    r.lambda_inset = std::isnan(inset) ? 0.0 : inset;
    return r;
}

}  // namespace

double AssemblyPushover::lagged_multiplier(const Scene& scene, double rotation) const {
    // semi-implicit Euler at 1e-4 s (at most 1e7 steps): the record is piecewise linear, the
    // mechanism slow against it
    const double dt = std::max(1e-4, scene.run.duration * 1e-7);
    double q = 0.0, v = 0.0;
    for (double t = 0.0; t <= scene.run.duration; t += dt) {
        const double lambda = record_sign * ground_multiplier(scene, t);
        const double acc = push * (lambda - this->lambda) / mass;
        if (q <= 0.0 && v <= 0.0 && acc <= 0.0) continue;   // held by its joints
        v += acc * dt;
        q = std::max(0.0, q + v * dt);
        if (q * turn >= rotation) return lambda;
    }
    return NAN;
}

CaseAnalysis analyse_assembly_pushover(const Scene& scene, const std::vector<Sample>& s, ContactKind contact,
                                       double threshold) {
    using namespace metrics;
    const AssemblyPushover a = assembly_pushover(scene);
    CaseAnalysis r;
    // the largest rotation of any free block from its orientation at t = 0
    for (const auto& x : s) {
        double largest = 0.0;
        for (size_t f = 0; f < x.blocks.size(); ++f)
            largest = std::max(largest, Eigen::AngleAxisd(s.front().blocks[f].orientation.conjugate() * x.blocks[f].orientation).angle());
        r.measured.t.push_back(x.t);
        r.measured.y.push_back(largest);
    }
    r.quantity = "largest rotation of a block, rad";
    const std::string name = "a/g when a block turns " + fixed_text(threshold, 4) + " rad";
    const double upper = a.lagged_multiplier(scene, threshold);
    const std::string la = "rigid-block limit analysis (" + std::to_string(a.interfaces) + " joints, μ = " +
                           fixed_text(scene.contact.friction, 3) + "): λ = " + fixed_text(a.lambda, 4);
    const bool slides = a.slip_share > kSlipShare;
    // the LP's friction is associative: a joint that slides must dilate (open by μ times its slip),
    // which Coulomb's joints do not, so where joints slide, or friction holds the static state up,
    // the true collapse can come earlier and by another mechanism (Drucker: the associative
    // multiplier bounds it from above)
    const bool leans = slides || a.friction_binds;
    const std::string friction_note =
        slides ? "; joints slide in its mechanism, and the LP's friction is associative (a sliding joint dilates): "
                 "Coulomb's joints collapse earlier, by another mechanism; shown, not judged"
        : a.friction_binds ? "; its static state leans on friction (10 % less friction lowers λ), which the LP takes as "
                             "associative: Coulomb's joints can give way earlier; shown, not judged"
                           : "";

    auto up = crossings(r.measured, threshold, Crossing::up);
    const double measured = up.empty() ? NAN : ground_multiplier(scene, up.front()) * a.record_sign;
    if (!up.empty()) r.event_time = up.front(), r.has_event = true;
    double peak = 0.0, largest = 0.0;   // the record's largest a/g along its push; the largest rotation
    for (size_t i = 0; i < r.measured.t.size(); ++i)
        peak = std::max(peak, a.record_sign * ground_multiplier(scene, r.measured.t[i])), largest = std::max(largest, r.measured.y[i]);
    if (peak < 0.98 * a.lambda) {
        // the record stays below λ: a statically admissible state carries it, nothing turns that far
        const std::string basis = la + " above the record's largest a/g " + fixed_text(peak, 4) +
                                  ": the assembly holds, no block turns " + fixed_text(threshold, 4) + " rad";
        if (contact.penalty || leans)
            r.metrics.push_back(info("largest rotation of a block", "rad", largest, threshold,
                                     basis + (leans ? friction_note : "; compliant joints take capacity off: shown, not judged")));
        else
            r.metrics.push_back(at_most("largest rotation of a block", "rad", largest, threshold, 0.0, basis));
        return r;
    }
    // from below: nothing turns that far before λ (2 %: the ramp's first swing on the joints);
    // penalty joints hinge inside the joint and take capacity off (docs/validation.md), so shown only
    // 2 % for the ramp's first swing on the joints, below the capacity left when every joint hinges
    // 1 mm inside its edge (an arch near its least thickness loses several per cent to that, a
    // stack a fraction of one)
    const double floor = 0.98 * std::min(a.lambda, a.lambda_inset);
    const std::string below = la + ", no block turns before it; 2 % below λ with every joint hinging " +
                              fixed_text(kInset * 1e3, 1) + " mm inside its edge (" + fixed_text(a.lambda_inset, 4) +
                              "), as a rigid engine's contact gives way" + friction_note;
    // a centred stack pushed at an angle to its sides on dem's overlap contact: its bed joints are
    // Winkler joints, which lean in two directions and open from a corner; their quasi-static path
    // peaks below λ, and past the peak the stack runs away, so nothing turns that far before it
    // (2 %, as above) where the path turns the top less than that at its peak
    const std::optional<oracle::BlockStack> stack =
        contact.penalty && contact.point_springs && scene.contact.scheme == ContactScheme::overlap && !leans
            ? centred_stack(scene)
            : std::nullopt;
    const double winkler_peak = stack ? stack->winkler_multiplier(scene.contact.kn) : NAN;
    const double peak_turn = stack ? stack->winkler_peak_rotation(scene.contact.kn) : NAN;
    if (std::isfinite(winkler_peak) && peak_turn < threshold && !up.empty())
        r.metrics.push_back(at_least(
            name + " (from below)", "", measured, 0.98 * winkler_peak,
            "the stack on no-tension Winkler bed joints of modulus kn (dem's overlap contact), pushed at " +
                fixed_text(std::abs(stack->push_angle) * 180.0 / M_PI, 1) +
                "° to its sides: the quasi-static peak " + fixed_text(winkler_peak, 4) + " of its path (the top turned " +
                fixed_text(peak_turn, 4) + " rad), past which it runs away (the " + la +
                "); 2 % for the ramp's first swing on the joints"));
    else if (contact.penalty)
        r.metrics.push_back(info(name + " (from below)", "", measured, a.lambda,
                                 la + ": compliant joints hinge inside their thickness and take capacity off (docs/"
                                      "validation.md, an arch under a lateral acceleration), so not judged from below"));
    else if (leans)
        r.metrics.push_back(info(name + " (from below)", "", measured, a.lambda, below));
    else if (up.empty())
        r.metrics.push_back(info(name + " (from below)", "", measured, a.lambda, below + " (never turned that far)"));
    else
        r.metrics.push_back(at_least(name + " (from below)", "", measured, floor, below));
    // from above: the linearised mechanism under the scene's record turns a block that far by
    // `upper` (its softening only hastens it); 2 % beyond it for the engines' own first swing
    const std::string above = "the limit analysis's mechanism as one degree of freedom (generalised mass " +
                              fixed_text(a.mass, 4) + " kg) pushed by the record past λ, without the geometric "
                              "softening that hastens it: an upper bound; 2 %";
    if (slides)   // the true mechanism, with joints that slide without dilating, is another one
        r.metrics.push_back(info(name + " (from above)", "", measured, upper, above + friction_note));
    else if (std::isnan(upper))
        r.metrics.push_back(info(name + " (from above)", "", measured, NAN, above + " (the record never drives it that far)"));
    else if (up.empty())
        r.metrics.push_back(missing(name + " (from above)", "", upper, 0.02, Check::at_most, above + " (never turned that far)"));
    else
        r.metrics.push_back(at_most(name + " (from above)", "", measured, upper, 0.02 * upper, above));
    return r;
}

}  // namespace cairn::cases
