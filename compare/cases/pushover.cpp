// a stack of blocks (column, wall) under a slowly ramped uniform ground acceleration: the a/g at
// which it overturns
#include <algorithm>
#include <cmath>
#include <map>

#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "cases/structure_kinds.hpp"
#include "output/number_format.hpp"
#include "error.hpp"

namespace cairn::cases {

namespace {

constexpr double kDefaultThreshold = 0.05;   // rad: well past any quasi-static equilibrium

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

oracle::BlockStack scene_stack(const Scene& scene) {
    if (!scene.ground_motion) throw Error(scene.source + ": a pushover reference needs a [ground_motion] table");
    if (scene.ground_motion->components.size() != 1)
        throw Error(scene.source + ": a pushover reference needs a [ground_motion] of one record");
    const Vec3 dir = scene.ground_motion->components.front().direction;
    Vec3 along = dir - dir.dot(scene.gravity.normalized()) * scene.gravity.normalized();
    if (along.norm() < 1e-9) throw Error(scene.source + ": a pushover reference needs a horizontal [ground_motion] direction");
    along.normalize();
    const Vec3 up = -scene.gravity.normalized(), across = up.cross(along);
    // layers by bottom height (to 1 µm), bottom first
    std::map<long long, std::vector<int>> by_bottom;
    for (size_t i = 0; i < scene.blocks.size(); ++i) {
        if (scene.blocks[i].fixed) continue;
        double zmin = INFINITY;
        for (const auto& c : scene.blocks[i].corners) zmin = std::min(zmin, (scene.blocks[i].orientation * c + scene.blocks[i].position).dot(up));
        by_bottom[std::llround(zmin * 1e6)].push_back(int(i));
    }
    oracle::BlockStack stack;
    stack.g = gravity(scene);
    for (const auto& [key, ids] : by_bottom) {
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, m = 0.0;
        for (int i : ids) {
            const BlockDef& b = scene.blocks[i];
            for (const auto& c : b.corners) {
                const Vec3 p = b.orientation * c + b.position;
                const double v[3] = {p.dot(along), p.dot(across), p.dot(up)};
                for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
            }
            m += block_mass(scene, i);
        }
        stack.layers.push_back({hi[2] - lo[2], hi[0] - lo[0], hi[1] - lo[1], m});
    }
    return stack;
}

CaseAnalysis analyse_pushover(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const auto& values = scene.reference->values;
    const double threshold = values.count("threshold") ? values.at("threshold") : kDefaultThreshold;
    const oracle::BlockStack stack = scene_stack(scene);
    const double quasi_static = stack.rigid_multiplier();
    const double t_ref = stack.rigid_ramp_time([&](double t) { return ground_multiplier(scene, t); }, threshold,
                                               scene.run.duration);
    const double lambda_ref = std::isnan(t_ref) ? NAN : ground_multiplier(scene, t_ref);

    CaseAnalysis r;
    r.measured = rotation_series(s, free_index(scene, scene.reference->block));
    r.quantity = "rotation of " + scene.blocks[scene.reference->block].name + ", rad";
    const std::string name = "a/g when the top turns " + fixed4(threshold) + " rad";
    const std::string basis = "rigid monolith about its base edge under the scene's ramp (RK4): B/H = " +
                              fixed4(quasi_static) + " plus the ramp's lag " + fixed4(lambda_ref - quasi_static) +
                              "; 2 %";
    auto up = crossings(r.measured, threshold, Crossing::up);
    if (up.empty()) {
        r.metrics.push_back(missing(name, "", lambda_ref, 0.02, Check::relative, basis + " (never turned that far)"));
        return r;
    }
    r.event_time = up.front();
    r.has_event = true;
    const double lambda = ground_multiplier(scene, up.front());
    r.metrics.push_back(relative(name, "", lambda, lambda_ref, 0.02, basis));
    r.metrics.push_back(info("a/g against the quasi-static multiplier", "", lambda, quasi_static,
                             "least over the mechanisms 'all above a bed joint turn about its edge': B/H"));
    if (contact.penalty)
        r.metrics.push_back(info("quasi-static peak of penalty joints", "", lambda, stack.winkler_multiplier(scene.contact.kn),
                                 "bed joints as no-tension springs kn integrated over the joint: they open gradually, "
                                 "so the stack leans and peaks below B/H (compare/analytic)"));
    return r;
}

// kind "pushover": no reference curve
static const CaseKind& pushover_kind() {
    static const FunctionKind k("pushover", {"threshold"}, analyse_pushover, nullptr, rigid_contact_only,
                                "rotation passes the threshold");
    return k;
}

namespace {
const KindRegistration pushover_registered(pushover_kind);
}  // namespace

}  // namespace cairn::cases
