// a block released on a plane inclined θ to the horizontal: it slides at g(sin θ − μ cos θ) when
// tan θ > μ, else it holds (only the elastic shear of its base)
#include <algorithm>
#include <cmath>

#include "analytic/oracles.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "output/number_format.hpp"

namespace cairn::cases {

namespace {

/// the plane of the scene: the downhill unit direction and its angle θ to the horizontal (rad),
/// from gravity and the face of the support (the first fixed block) the block rests on; the
/// reference's `angle`, when given, must agree
struct Plane {
    Vec3 down;
    double angle;
};

/// the outward normal (world) of the side of a general hexahedron `support` that `block` rests on:
/// of the sides whose plane the block's centre of mass lies beyond, the one facing most against
/// gravity `g` (unit); boxes are read so already (upright_frames: their frame z)
Vec3 resting_face_normal(const BlockDef& support, const BlockDef& block, const Vec3& g) {
    const Vec3 on = block.position + block.orientation * mass_properties(block.corners, 1.0).centre;
    Vec3 best = -g;
    double up = -2.0;
    for (const auto& side : placed_sides(support))
        if (side.normal.dot(on - side.corner) > 0.0 && -g.dot(side.normal) > up) up = -g.dot(side.normal), best = side.normal;
    return best;
}

Plane plane(const Scene& scene) {
    const BlockDef* support = nullptr;
    for (const auto& b : scene.blocks)
        if (b.fixed) { support = &b; break; }
    if (!support) throw Error(scene.source + ": an incline reference needs a fixed block as its plane");
    const Vec3 g = scene.gravity.normalized();
    const Vec3 n = support->shape == Shape::box ? Vec3(support->orientation * Vec3::UnitZ())
                                                : resting_face_normal(*support, scene.blocks.at(size_t(scene.reference->block)), g);
    const Vec3 along = g - g.dot(n) * n;
    Plane p{along.norm() > 1e-12 ? Vec3(along.normalized()) : Vec3::UnitX(), std::acos(std::clamp(-g.dot(n), -1.0, 1.0))};
    const auto it = scene.reference->values.find("angle");
    // 1e-3 rad: an angle written to four decimals in degrees or radians
    if (it != scene.reference->values.end() && std::abs(it->second - p.angle) > 1e-3)
        throw Error(scene.source + ": [reference] angle = " + message_number(it->second, 6) +
                    " rad, but the top face of block '" + support->name + "' is inclined " +
                    message_number(p.angle, 6) + " rad to the horizontal");
    return p;
}

/// displacement of the reference block's centre of mass down the plane, from its start, m
metrics::Series downhill(const Scene& scene, const std::vector<Sample>& s, const Vec3& down) {
    const int f = free_index(scene, scene.reference->block);
    metrics::Series out{times(s), {}};
    for (const auto& x : s) out.y.push_back((x.blocks.at(f).position - s.front().blocks.at(f).position).dot(down));
    return out;
}

/// the reference block's launch speed down the plane's fall line, m/s (+ downhill; 0 released at rest)
double launch_speed(const Scene& scene, const Plane& p) {
    return scene.blocks.at(size_t(scene.reference->block)).velocity.dot(p.down);
}

/// refuses a drive the incline oracle leaves out: loads, a record, a spin, a launch off the fall line
void check_incline(const Scene& scene) {
    require_drive_modelled(scene, "incline", {false, true});
    require_alone(scene, "incline");
    const BlockDef& d = scene.blocks.at(size_t(scene.reference->block));
    const Plane p = plane(scene);
    // 1e-3 of the speed: a launch typed to 3-4 digits is along the line (as the plane's angle, 1e-3 rad)
    const double off = (d.velocity - d.velocity.dot(p.down) * p.down).norm();
    if (d.angular_velocity.norm() > 0.0 || off > 1e-3 * d.velocity.norm())
        throw Error(scene.source + ": reference.kind = \"incline\": blocks." + d.name +
                    ".velocity/angular_velocity: the incline's block is launched along the plane's fall line only (no "
                    "spin, no speed across it or off the plane; down the line is " + message_vector(p.down) +
                    ", the speed off it " + message_number(off) + " m/s)");
}

/// the launched block's displacement down the plane at the times `t`, m
std::vector<double> launched_curve(const Scene& scene, const Plane& p, double v0, const std::vector<double>& t) {
    std::vector<double> out;
    for (double x : t) out.push_back(oracle::launched_on_incline(gravity(scene), p.angle, scene.contact.friction, v0, x));
    return out;
}

std::vector<double> incline_curve(const Scene& scene, ContactKind, const std::vector<double>& t) {
    const Plane p = plane(scene);
    if (const double v0 = launch_speed(scene, p); v0 != 0.0) return launched_curve(scene, p, v0, t);
    const double a = oracle::incline_acceleration(gravity(scene), p.angle, scene.contact.friction);
    std::vector<double> out;
    if (a <= 0.0) return out;   // held: the elastic shear only, judged by its drift
    for (double x : t) out.push_back(0.5 * a * x * x);
    return out;
}

/// a launched block: judged on its final displacement and, launched uphill, its highest point
void judge_launch(const Scene& scene, const Plane& p, double v0, ContactKind contact, CaseAnalysis& r) {
    using namespace metrics;
    r.analytic = launched_curve(scene, p, v0, r.measured.t);
    r.analytic_label = "launched at v0: braked by g(sin θ + μ cos θ) uphill, g(sin θ − μ cos θ) downhill";
    r.analytic_key = "launched block";
    double lowest = 0.0, largest = 0.0;   // the reference's least and largest displacement, m
    for (double x : r.analytic) lowest = std::min(lowest, x), largest = std::max(largest, std::abs(x));
    const int b = scene.reference->block;
    double allowance = 0.01 * largest;
    std::string why = "1 % of the largest displacement: the engines' contact and step";
    if (contact.penalty && scene.contact.ks > 0.0) {   // the shear springs stretch before they slide
        const double stretch = scene.contact.friction * block_mass(scene, b) * gravity(scene) * std::cos(p.angle) /
                               (scene.contact.ks * contact_area(scene));
        allowance += stretch;
        why = "1 % of the largest displacement, plus the shear springs' stretch μ·m·g·cos θ/(ks·A) = " +
              message_number(stretch) + " m";
    }
    r.metrics.push_back(absolute("final displacement down the plane", "m", r.measured.y.back(), r.analytic.back(),
                                 allowance, why));
    if (v0 < 0.0) {
        double highest = 0.0;
        for (double x : r.measured.y) highest = std::min(highest, x);
        r.metrics.push_back(absolute("highest point (up the plane)", "m", highest, lowest, allowance,
                                     why + "; v0²/(2g(sin θ + μ cos θ)) up the plane"));
    }
    const auto half = crossings(r.measured, 0.5 * r.analytic.back(), r.analytic.back() > 0.0 ? Crossing::up : Crossing::down);
    if (!half.empty()) r.event_time = half[0], r.has_event = true;
}

CaseAnalysis judged_incline(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const Plane p = plane(scene);
    const int b = scene.reference->block;
    const double g = gravity(scene), mu = scene.contact.friction, T = s.back().t;
    const double acc = oracle::incline_acceleration(g, p.angle, mu);
    CaseAnalysis r;
    r.measured = downhill(scene, s, p.down);
    r.quantity = "displacement of A's centre of mass down the plane, m";
    if (const double v0 = launch_speed(scene, p); v0 != 0.0) {
        judge_launch(scene, p, v0, contact, r);
        return r;
    }
    if (acc > 0.0) {
        r.analytic = incline_curve(scene, {}, r.measured.t);
        r.analytic_label = "s = a t²/2, a = g (sin θ − μ cos θ)";
        // as the pulled block: skip the first 10 % (the shear spring's start-up), fit a quadratic
        const auto c = polyfit(r.measured, 2, 0.1 * T, T);
        r.metrics.push_back(relative("sliding acceleration", "m/s²", 2.0 * c[2], acc, 0.01,
                                     "g (sin θ − μ cos θ), quadratic fit over the last 90 % of the run; 1 %"));
        const auto half = crossings(r.measured, 0.25 * acc * T * T, Crossing::up);
        if (!half.empty()) r.event_time = half[0], r.has_event = true;
        return r;
    }
    // holds (tan θ ≤ μ): no progressive slip over the second half of the run, against the elastic
    // shear of the base m g sin θ / (ks A)
    const double elastic = block_mass(scene, b) * g * std::sin(p.angle) / (scene.contact.ks * contact_area(scene));
    r.metrics.push_back(slip_while_held(r.measured, 0.5 * T, T, 0.05 * elastic,
                                        "tan θ ≤ μ; the second half of the run; 5 % of the elastic base shear m g sin "
                                        "θ/(ks A) = " + message_number(elastic, 6) + " m, as the stick case"));
    return r;
}

/// the run judged, a deformable block compliant against its joints shown instead (show_if_flexible)
CaseAnalysis analyse_incline(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    CaseAnalysis r = judged_incline(scene, s, contact);
    show_if_flexible(scene, contact, r.metrics);
    return r;
}

}  // namespace

// kind "incline": Coulomb's law holds for rigid contact
static const CaseKind& incline_kind() {
    static const FunctionKind k("incline", {"angle"}, analyse_incline, incline_curve, rigid_contact_only,
                                "slid half the reference distance", check_incline);
    return k;
}

namespace {
const KindRegistration incline_registered(incline_kind);
}  // namespace

}  // namespace cairn::cases
