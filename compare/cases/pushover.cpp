// a stack of blocks (column, wall) under a slowly ramped uniform ground acceleration: the a/g at
// which it overturns; and the scene's free blocks read as such a stack (scene_stack.hpp)
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "cases/assembly_pushover.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "cases/structure_kinds.hpp"
#include "output/number_format.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "geometry/overlap.hpp"

namespace cairn::cases {

namespace {

constexpr double kDefaultThreshold = 0.05;   // rad: well past any quasi-static equilibrium
// rad: a push this close to a layer's side is along it, as the other kinds take an angle written
// to four decimals in degrees (a direction or a turn written to six digits is 1e-6 off)
constexpr double kSideAngle = 1e-3;

/// the rotation angle (rad) of free block f from its orientation at t = 0
metrics::Series rotation_series(const std::vector<Sample>& s, int f) {
    metrics::Series r;
    const Quat q0 = s.front().blocks.at(f).orientation;
    for (const auto& x : s) {
        r.t.push_back(x.t);
        r.y.push_back(Eigen::AngleAxisd(q0.conjugate() * x.blocks.at(f).orientation).angle());
    }
    return r;
}

std::string fixed4(double x) { return fixed_text(x, 4); }

}  // namespace

double ground_multiplier(const Scene& scene, double t) {
    if (!scene.ground_motion) return 0.0;
    return scene.ground_motion->components.front().acceleration.at(t - scene.ground_motion->start) / gravity(scene);
}

namespace {

/// a layer of the free blocks: its bounds along, across and up, its mass and its blocks' volume
struct LayerBounds {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    double mass = 0.0;     ///< kg
    double volume = 0.0;   ///< m³, the blocks' own (less than the bounds' where a course has gaps)
    int blocks = 0;        ///< how many
    double thinnest[2] = {INFINITY, INFINITY};   ///< m: the least extent of one of its blocks along and across
};

/// the direction of the scene's one horizontal record, or nothing
std::optional<Vec3> push_direction(const Scene& scene) {
    if (!scene.ground_motion || scene.ground_motion->components.size() != 1) return std::nullopt;
    const Vec3 dir = scene.ground_motion->components.front().direction, up = -scene.gravity.normalized();
    const Vec3 along = dir - dir.dot(up) * up;
    if (along.norm() < 1e-9) return std::nullopt;
    return along.normalized();
}

/// the world corners of a block as placed, m
Corners world_corners(const BlockDef& b) { return placed_corners(b.corners, b.position, b.orientation); }

/// the free blocks grouped into layers by their bottom height (to 1 µm), bottom first, in the
/// frame (along, across, up)
std::vector<LayerBounds> layers_of(const Scene& scene, const Vec3& along) {
    const Vec3 up = -scene.gravity.normalized(), across = up.cross(along);
    std::map<long long, std::vector<int>> by_bottom;
    for (size_t i = 0; i < scene.blocks.size(); ++i) {
        if (scene.blocks[i].fixed) continue;
        double zmin = INFINITY;
        for (const auto& p : world_corners(scene.blocks[i])) zmin = std::min(zmin, p.dot(up));
        by_bottom[std::llround(zmin * 1e6)].push_back(int(i));
    }
    std::vector<LayerBounds> layers;
    for (const auto& [key, ids] : by_bottom) {
        LayerBounds l;
        for (int i : ids) {
            double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
            for (const auto& p : world_corners(scene.blocks[size_t(i)])) {
                const double v[3] = {p.dot(along), p.dot(across), p.dot(up)};
                for (int k = 0; k < 3; ++k) l.lo[k] = std::min(l.lo[k], v[k]), l.hi[k] = std::max(l.hi[k], v[k]);
                for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
            }
            for (int k = 0; k < 2; ++k) l.thinnest[k] = std::min(l.thinnest[k], hi[k] - lo[k]);
            l.mass += block_mass(scene, i);
            ++l.blocks;
            l.volume += mass_properties(scene.blocks[size_t(i)].corners, 1.0).volume;
        }
        layers.push_back(l);
    }
    return layers;
}

oracle::BlockStack stack_of(const Scene& scene, const std::vector<LayerBounds>& layers) {
    oracle::BlockStack stack;
    stack.g = gravity(scene);
    for (const auto& l : layers) stack.layers.push_back({l.hi[2] - l.lo[2], l.hi[0] - l.lo[0], l.hi[1] - l.lo[1], l.mass});
    return stack;
}

}  // namespace

oracle::BlockStack scene_stack(const Scene& scene) {
    if (!scene.ground_motion) throw Error(scene.source + ": a pushover reference needs a [ground_motion] table");
    if (scene.ground_motion->components.size() != 1)
        throw Error(scene.source + ": a pushover reference needs a [ground_motion] of one record");
    const auto along = push_direction(scene);
    if (!along) throw Error(scene.source + ": a pushover reference needs a horizontal [ground_motion] direction");
    return stack_of(scene, layers_of(scene, *along));
}

namespace {

/// the horizontal direction of the first free block's first axis that is not its most vertical
/// one: the layers' first axis when the blocks stand square to each other
std::optional<Vec3> layer_axis(const Scene& scene) {
    const Vec3 up = -scene.gravity.normalized();
    for (const auto& b : scene.blocks) {
        if (b.fixed) continue;
        const Eigen::Matrix3d r = b.orientation.toRotationMatrix();
        int vertical = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(r.col(k).dot(up)) > std::abs(r.col(vertical).dot(up))) vertical = k;
        const Vec3 a = r.col(vertical == 0 ? 1 : 0);
        const Vec3 flat = a - a.dot(up) * up;
        if (flat.norm() < 1e-9) return std::nullopt;
        return flat.normalized();
    }
    return std::nullopt;
}

}  // namespace

std::optional<oracle::BlockStack> centred_stack(const Scene& scene, std::string* why) {
    auto refuse = [&](const std::string& reason) -> std::optional<oracle::BlockStack> {
        if (why) *why = reason;
        return std::nullopt;
    };
    const auto push = push_direction(scene);
    if (!push) return refuse("ground_motion: one record along a horizontal direction is needed");
    const auto axis = layer_axis(scene);
    if (!axis) return refuse("blocks: no free block stands with a horizontal axis");
    const Vec3 up = -scene.gravity.normalized(), across = up.cross(*axis);
    const double angle = std::atan2(push->dot(across), push->dot(*axis));
    // along one of the layers' axes (0 or 1), or -1 for a push at an angle to both (within
    // kSideAngle: a direction or a turn written to six digits)
    const int push_axis = std::abs(std::sin(angle)) < kSideAngle ? 0 : std::abs(std::cos(angle)) < kSideAngle ? 1 : -1;
    const auto layers = layers_of(scene, *axis);
    if (layers.empty()) return refuse("blocks: no free block");
    const LayerBounds& first = layers.front();
    const double height = layers.back().hi[2] - first.lo[2];
    for (size_t k = 0; k < layers.size(); ++k) {
        const LayerBounds& l = layers[k];
        const std::string layer = "blocks: the layer " + std::to_string(k + 1) + " from the bottom ";
        const double box = (l.hi[0] - l.lo[0]) * (l.hi[1] - l.lo[1]) * (l.hi[2] - l.lo[2]);
        if (std::abs(l.volume - box) > 1e-3 * box)
            return refuse(layer + "has gaps or blocks not square to each other (not one full box)");
        // within 1e-3 of the thinner layer's height, as the first on its base: positions written
        // to six digits leave gaps of microns, which the contact closes at once
        if (k > 0 && std::abs(l.lo[2] - layers[k - 1].hi[2]) >
                         1e-6 * height + 1e-3 * std::min(l.hi[2] - l.lo[2], layers[k - 1].hi[2] - layers[k - 1].lo[2]))
            return refuse(layer + "does not rest on the one below");
        // a course of several blocks turns as one only where each of them spans the course along
        // the push (a wall pushed out of its plane); pushed across their head joints, or at an
        // angle to them, its blocks lean on each other and rock apart, which the layers do not model
        if (l.blocks > 1 &&
            (push_axis < 0 || l.thinnest[push_axis] < (1 - 1e-3) * (l.hi[push_axis] - l.lo[push_axis])))
            return refuse(layer + "holds several blocks that do not each span it along the push (pushed across "
                                  "their joints they rock apart; the layers turn as one only pushed along their joints)");
        for (int a : {0, 1})   // centred on the first layer's vertical axis
            if (std::abs((l.lo[a] + l.hi[a]) - (first.lo[a] + first.hi[a])) > 0.02 * (first.hi[a] - first.lo[a]))
                return refuse(layer + "is off the first layer's vertical axis by more than 1 % of its width");
    }
    // on a fixed block whose top is the first layer's bottom and which runs past it along the push
    // (past both its sides for a push at an angle: it tips over a corner)
    for (const auto& b : scene.blocks) {
        if (!b.fixed) continue;
        double top = -INFINITY, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (const auto& p : world_corners(b)) {
            top = std::max(top, p.dot(up));
            const double v[2] = {p.dot(*axis), p.dot(across)};
            for (int a : {0, 1}) lo[a] = std::min(lo[a], v[a]), hi[a] = std::max(hi[a], v[a]);
        }
        bool past = true;
        for (int a : {0, 1})
            if (push_axis < 0 || push_axis == a) past = past && lo[a] < first.lo[a] && hi[a] > first.hi[a];
        if (std::abs(top - first.lo[2]) <= 1e-6 * height + 1e-3 * (first.hi[2] - first.lo[2]) && past) {
            oracle::BlockStack stack = stack_of(scene, layers);
            stack.push_angle = angle;
            return stack;
        }
    }
    return refuse("blocks: no fixed block under the first layer that runs past it along the push");
}

namespace {

/// the centred stack of a scene pushed along one of its layers' sides, or nothing: the stack
/// oracle's monolith turns about an edge; anything else is read as a block assembly
std::optional<oracle::BlockStack> stack_along_a_side(const Scene& scene) {
    auto stack = centred_stack(scene);
    if (stack && std::min(std::abs(std::sin(stack->push_angle)), std::abs(std::cos(stack->push_angle))) >= kSideAngle)
        stack.reset();
    return stack;
}

/// refuses, naming the key, a pushover scene neither oracle models (assembly_pushover.hpp says what)
void check_pushover(const Scene& scene) {
    require_pushover_drive(scene);
    if (!stack_along_a_side(scene)) assembly_pushover(scene);
}

}  // namespace

CaseAnalysis analyse_pushover(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const auto& values = scene.reference->values;
    const double threshold = values.count("threshold") ? values.at("threshold") : kDefaultThreshold;
    if (!stack_along_a_side(scene)) return analyse_assembly_pushover(scene, s, contact, threshold);
    const oracle::BlockStack stack = scene_stack(scene);
    const double quasi_static = stack.rigid_multiplier();
    auto ramp = [&](double t) { return ground_multiplier(scene, t); };
    const double t_rigid = stack.rigid_ramp_time(ramp, threshold, scene.run.duration);
    const double lambda_rigid = std::isnan(t_rigid) ? NAN : ground_multiplier(scene, t_rigid);
    // dem's overlap contact integrates kn over each bed joint: a Winkler joint, whose stack leans
    // and peaks below B/H (as ground_rocking judges dem on its Winkler base); the paper's grid puts
    // the weight on its edge row and an engine's matched contact matches only kn·A of a face, so
    // those are judged, as rigid contact is, against the rigid monolith
    const bool winkler = contact.penalty && contact.point_springs && scene.contact.scheme == ContactScheme::overlap;
    const double t_winkler = winkler ? stack.winkler_ramp_time(scene.contact.kn, ramp, threshold, scene.run.duration) : NAN;
    const double lambda_winkler = std::isnan(t_winkler) ? NAN : ground_multiplier(scene, t_winkler);
    const double peak = contact.penalty ? stack.winkler_multiplier(scene.contact.kn) : NAN;

    // the lag behind the quasi-static value, where the oracle turns that far within the run
    auto lag = [](double d) {
        return std::isnan(d) ? std::string(" (under this ramp it does not turn that far within the run)")
                             : " plus the ramp's lag " + fixed4(d);
    };
    CaseAnalysis r;
    r.measured = rotation_series(s, free_index(scene, scene.reference->block));
    r.quantity = "rotation of " + scene.blocks[scene.reference->block].name + ", rad";
    const std::string name = "a/g when the top turns " + fixed4(threshold) + " rad";
    const std::string rigid_basis =
        "the layers above the critical bed joint as one rigid body about its edge under the scene's ramp (RK4): B/H = " +
        fixed4(quasi_static) + lag(lambda_rigid - quasi_static);
    const std::string winkler_basis =
        "the stack on no-tension Winkler bed joints of modulus kn (dem's overlap contact): the monolith's rocking "
        "equation with the joints' quasi-static multiplier in place of the rigid one, under the scene's ramp (RK4): "
        "its peak " + fixed4(peak) + lag(lambda_winkler - peak) +
        "; 2 % (the path's mechanism taken as one degree of freedom; shear springs and block strains left out)";
    const double lambda_ref = winkler ? lambda_winkler : lambda_rigid;
    const std::string basis = winkler ? winkler_basis : rigid_basis + "; 2 %";
    auto up = crossings(r.measured, threshold, Crossing::up);
    if (!up.empty()) r.event_time = up.front(), r.has_event = true;
    double largest = 0.0;
    for (double y : r.measured.y) largest = std::max(largest, std::abs(y));
    const std::string largest_name = "largest rotation of " + scene.blocks[scene.reference->block].name;
    // the Winkler continuation found no peak, or ends before the threshold: no reference
    if (winkler && (std::isnan(peak) || threshold >= oracle::BlockStack::kWinklerPathEnd)) {
        const std::string why = "not judged: the Winkler stack's path found no peak before the threshold (its "
                                "continuation lost, or the threshold past its end); against the " + rigid_basis;
        if (up.empty())
            r.metrics.push_back(info(largest_name, "rad", largest, threshold, why));
        else
            r.metrics.push_back(info(name, "", ground_multiplier(scene, up.front()), lambda_rigid, why));
        return r;
    }
    if (std::isnan(lambda_ref)) {
        // the reference does not turn that far within the run: neither may the stack
        double record = 0.0;
        for (double t : r.measured.t) record = std::max(record, std::abs(ground_multiplier(scene, t)));
        r.metrics.push_back(at_most(largest_name, "rad", largest, threshold, 0.0,
                                    (winkler ? winkler_basis : rigid_basis) + ": under the record's largest a/g " +
                                        fixed4(record) + " it does not turn " + fixed4(threshold) +
                                        " rad within the run"));
        return r;
    }
    if (up.empty()) {
        r.metrics.push_back(missing(name, "", lambda_ref, 0.02, Check::relative, basis + " (never turned that far)"));
        return r;
    }
    const double lambda = ground_multiplier(scene, up.front());
    r.metrics.push_back(relative(name, "", lambda, lambda_ref, 0.02, basis));
    if (winkler)
        r.metrics.push_back(info("a/g against the rigid monolith", "", lambda, lambda_rigid, rigid_basis));
    r.metrics.push_back(info("a/g against the quasi-static multiplier", "", lambda, quasi_static,
                             "least over the mechanisms 'all above a bed joint turn about its edge': B/H"));
    if (contact.penalty)
        r.metrics.push_back(info("quasi-static peak of penalty joints", "", lambda, peak,
                                 "bed joints as no-tension springs kn integrated over the joint: they open gradually, "
                                 "so the stack leans and peaks below B/H (compare/analytic)"));
    return r;
}

// kind "pushover": no reference curve
static const CaseKind& pushover_kind() {
    static const FunctionKind k("pushover", {"threshold"}, analyse_pushover, nullptr, rigid_contact_only,
                                "rotation passes the threshold", check_pushover);
    return k;
}

namespace {
const KindRegistration pushover_registered(pushover_kind);
}  // namespace

}  // namespace cairn::cases
