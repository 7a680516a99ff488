// case (c): a block pushed by H on a flat base, sliding (H > μW) or holding (H < μW)
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analytic/oracles.hpp"
#include "analytic/winkler_block.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "output/number_format.hpp"

namespace cairn::cases {

namespace {

/// the load on the reference block (the first one acting on it), or nullptr
const LoadDef* pull(const Scene& scene) {
    for (const auto& l : scene.loads)
        if (l.block == scene.reference->block) return &l;
    return nullptr;
}

/// the horizontal unit direction of the loads on the reference block (their sum), +x if none
Vec3 push_direction(const Scene& scene) {
    Vec3 sum = Vec3::Zero();
    for (const auto& l : scene.loads) sum += l.force;
    const Vec3 up = -scene.gravity.normalized();
    const Vec3 h = sum - sum.dot(up) * up;
    return h.norm() > 0.0 ? Vec3(h.normalized()) : Vec3::UnitX();
}

/// the reference block on a Winkler base with the scene's law, and the height (m) of the load above
/// its base: its base's length along the push and across it (world), the load point's and the
/// centre of mass's heights above its lowest corner
oracle::WinklerBlock winkler(const Scene& scene, double* height) {
    const int a = scene.reference->block;
    const BlockDef& d = scene.blocks.at(size_t(a));
    const Vec3 up = -scene.gravity.normalized(), along = push_direction(scene), across = up.cross(along);
    double xlo = 1e300, xhi = -1e300, ylo = 1e300, yhi = -1e300, zlo = 1e300;
    for (const auto& corner : d.corners) {
        const Vec3 c = d.orientation * corner;
        xlo = std::min(xlo, c.dot(along)), xhi = std::max(xhi, c.dot(along));
        ylo = std::min(ylo, c.dot(across)), yhi = std::max(yhi, c.dot(across));
        zlo = std::min(zlo, c.dot(up));
    }
    const LoadDef* l = pull(scene);
    *height = l ? (d.orientation * l->point).dot(up) - zlo : 0.0;
    oracle::WinklerBlock wb{xhi - xlo, yhi - ylo, scene.contact.kn, scene.contact.ks, scene.contact.friction,
                            block_mass(scene, a) * gravity(scene)};
    wb.com_height = (d.orientation * mass_properties(d.corners, 1.0).centre).dot(up) - zlo;
    return wb;
}

/// the reference block's moment of inertia about the edge of its base on the push's side, kg·m²
double toe_inertia(const Scene& scene) {
    const int a = scene.reference->block;
    const BlockDef& d = scene.blocks.at(size_t(a));
    const Vec3 up = -scene.gravity.normalized(), along = push_direction(scene), across = up.cross(along);
    const auto mp = mass_properties(d.corners, 1.0);
    const double m = block_mass(scene, a);
    const Mat3 r = d.orientation.toRotationMatrix(), inertia = r * mp.inertia * r.transpose() * (m / mp.mass);
    double toe = -1e300, zlo = 1e300;
    for (const auto& corner : d.corners) {
        const Vec3 c = d.orientation * (corner - mp.centre);
        toe = std::max(toe, c.dot(along)), zlo = std::min(zlo, c.dot(up));
    }
    return across.dot(inertia * across) + m * (toe * toe + zlo * zlo);
}

/// refuses a drive the friction oracle leaves out: a ground motion, loads on other blocks, an
/// initial velocity, loads on the block whose sum is not the reference's horizontal `force`, a
/// push that twists the block about the vertical, loads at different heights, a push at an
/// angle to the sides of an upright block (the oracle is the block on a Winkler base in the
/// vertical plane of the push), or a push that tips the block (held or sliding)
void check_friction(const Scene& scene) {
    require_drive_modelled(scene, scene.reference->kind, {true, false});
    require_alone(scene, scene.reference->kind);
    Vec3 sum = Vec3::Zero();
    for (const auto& l : scene.loads) sum += l.force;
    const Vec3 up = -scene.gravity.normalized();
    const double horizontal = (sum - sum.dot(up) * up).norm(), H = scene.reference->values.at("force");
    const std::string key = scene.source + ": reference.force = " + message_number(H, 6) + " N: ";
    // 1e-6 of the force: a value written to seven digits
    if (std::abs(sum.dot(up)) > 1e-6 * sum.norm() || std::abs(horizontal - H) > 1e-6 * std::max(H, horizontal)) {
        char why[200];
        std::snprintf(why, sizeof why, "the loads on its block sum to %.7g N horizontal and %.7g N vertical", horizontal,
                      sum.dot(up));
        throw Error(key + why + "; the friction reference models one horizontal force of that size");
    }
    const BlockDef& b = scene.blocks.at(size_t(scene.reference->block));
    const Vec3 d = push_direction(scene), centre = mass_properties(b.corners, 1.0).centre;
    double size = 0.0;
    for (const auto& c : b.corners) size = std::max(size, (c - centre).norm());
    double twist = 0.0, h0 = NAN;
    for (const auto& l : scene.loads) {
        const Vec3 r = b.orientation * (l.point - centre);   // from the centre of mass, world
        twist += r.cross(l.force).dot(up);
        const double h = r.dot(up);
        if (std::isnan(h0)) h0 = h;
        if (std::abs(h - h0) > 1e-6 * size)
            throw Error(key + "its loads act at different heights (" + message_number(h0, 6) + " and " + message_number(h, 6) +
                        " m above the centre of mass); the friction reference models one force at one height");
    }
    if (std::abs(twist) > 1e-6 * H * size) {
        char why[240];
        std::snprintf(why, sizeof why,
                      "its loads twist the block about the vertical through its centre of mass by %.4g N·m (the "
                      "push's line of action misses the centre by %.4g m)",
                      twist, std::abs(twist) / H);
        throw Error(key + why + "; the friction reference (a block on a Winkler base in the plane of the push) "
                                "leaves out the base's resistance to torsion");
    }
    // upright; held, pushed along one of its sides (the Winkler block lies in the push's vertical
    // plane); sliding, in any direction (Coulomb's friction is isotropic: (H/W − μ)g along the push)
    const bool slides = scene.reference->kind == "slide";
    const Vec3 ax = b.orientation * Vec3::UnitX(), ay = b.orientation * Vec3::UnitY(), az = b.orientation * Vec3::UnitZ();
    const bool along_side = std::min(1 - std::abs(ax.dot(d)), 1 - std::abs(ay.dot(d))) <= 1e-9;
    if (std::abs(az.dot(up)) < 1 - 1e-9)
        throw Error(key + "the block is not upright (none of its axes is along −gravity: it is tilted); the friction "
                          "reference models a block standing on one of its sides on a horizontal base");
    if (!slides && !along_side)
        throw Error(key + "the push is not along a side of the block; the stick reference models a block pushed "
                          "along one of its sides (the Winkler block in the push's vertical plane)");
    // the base's reaction must stay inside the base: held, W·e = H·h (on springs plus the weight's
    // shift over the tilt); sliding at (H − μW)/m, W·e = H·h − (H − μW)·h_c. Along a side the base
    // runs half its width from the centre; at an angle to the sides, to the nearer of the two
    // edges the push's line crosses, min(a/|cos|, b/|sin|) with a, b the base's half sides
    double h = 0.0;
    const auto wb = winkler(scene, &h);
    double half = 0.5 * wb.width;
    if (!along_side) {
        const Vec3 centre_w = b.orientation * centre;
        double a_half = 0.0, b_half = 0.0;
        for (const auto& c : b.corners) {
            const Vec3 r = b.orientation * c - centre_w;
            a_half = std::max(a_half, std::abs(r.dot(ax))), b_half = std::max(b_half, std::abs(r.dot(ay)));
        }
        half = std::min(a_half / std::abs(ax.dot(d)), b_half / std::abs(ay.dot(d)));
    }
    const double W = wb.weight;
    const double e = slides ? (H * h - (H - wb.mu * W) * wb.com_height) / W : H * h / W;
    const double on_springs = slides ? e : std::abs(wb.eccentricity(H, h));
    if (std::abs(e) >= half || !(on_springs < half)) {
        char why[400];
        std::snprintf(why, sizeof why,
                      "the push tips the block%s: the base's reaction falls %.4g m from the centre of its %.4g m base "
                      "(%s)%s; the friction reference models a block that %s upright",
                      slides ? " as it slides" : "", std::abs(e), wb.width,
                      slides ? "H·h − (H − μW)·h_c over W" : "H·h/W",
                      std::abs(e) < half ? ", and on the springs of modulus kn the weight's shift over the tilt carries it "
                                           "past the edge"
                                         : "",
                      slides ? "slides" : "stays");
        throw Error(key + why);
    }
}

/// the series of a material point's position along the push, m: block-frame point `local` of the
/// reference block (the samples carry its centre of mass and orientation); from its first sample
/// when `relative`
metrics::Series along_push(const Scene& scene, const std::vector<Sample>& s, const Vec3& local, bool relative) {
    const Vec3 d = push_direction(scene);
    const int f = free_index(scene, scene.reference->block);
    const Vec3 com = mass_properties(scene.blocks.at(size_t(scene.reference->block)).corners, 1.0).centre;
    metrics::Series out;
    for (const auto& x : s) {
        const BlockState& b = x.blocks.at(size_t(f));
        out.t.push_back(x.t);
        out.y.push_back((b.position + b.orientation * (local - com)).dot(d));
    }
    if (relative && !out.y.empty()) {
        const double y0 = out.y.front();
        for (double& y : out.y) y -= y0;
    }
    return out;
}

/// the centre of the reference block's base, block frame: the probe named "base" where the scene
/// has one, else under the centre of mass at the lowest corner's height (the block is upright)
Vec3 base_centre(const Scene& scene) {
    const int p = probe_index(scene, "base");
    if (p >= 0) return scene.probes.at(size_t(p)).point;
    const BlockDef& b = scene.blocks.at(size_t(scene.reference->block));
    Vec3 c = mass_properties(b.corners, 1.0).centre;
    double zlo = 1e300;
    for (const auto& corner : b.corners) zlo = std::min(zlo, corner.z());
    c.z() = zlo;
    return c;
}

std::vector<double> friction_curve(const Scene& scene, ContactKind, const std::vector<double>& t) {
    const int a = scene.reference->block;
    const double m = block_mass(scene, a), g = gravity(scene), H = scene.reference->values.at("force");
    const LoadDef* l = pull(scene);
    std::vector<double> out;
    if (scene.reference->kind == "slide") {
        const double acc = oracle::pulled_block_acceleration(m, g, H, scene.contact.friction);
        for (double x : t) out.push_back(0.5 * acc * x * x);
    } else {
        // quasi-static base shear u(H(t)) of the block on a Winkler base, tabulated at 201 load
        // levels and interpolated (the full-contact-with-slip range needs a bisection per level)
        double h = 0.0;
        const auto wb = winkler(scene, &h);
        std::vector<double> table(201);
        for (size_t i = 0; i < table.size(); ++i) table[i] = wb.shear_displacement(H * double(i) / 200.0, h);
        for (double x : t) {
            const double f = std::clamp(l ? l->factor(x) : 1.0, 0.0, 1.0) * 200.0;
            const size_t i = std::min<size_t>(size_t(f), 199);
            out.push_back(table[i] + (f - double(i)) * (table[i + 1] - table[i]));
        }
    }
    return out;
}

/// the mean base displacement over [t0, T] against the scene's Winkler block `wb` under its load
/// at height h (m), whose quasi-static base shear is u_ref (m); judged where that oracle holds:
/// the load ramped slowly against the block's rocking and shear modes on its springs, the swings
/// died out, and the contact zone spans three or more of the contact's shear springs along the push
metrics::Metric base_shear_metric(const Scene& scene, const oracle::WinklerBlock& wb, double h, double u_ref,
                                  const metrics::Series& u, double t0, double T, const metrics::HeldDrift& held,
                                  ContactKind contact) {
    using namespace metrics;
    const double H = scene.reference->values.at("force");
    const double e = wb.eccentricity(H, h), c = wb.contact_length(e);
    const double elastic = H / (scene.contact.ks * contact_area(scene)), mean = mean_value(u, t0, T);
    char why[600];
    if (e > wb.width / 6.0)
        std::snprintf(why, sizeof why,
                      "Winkler block, e = H·h/W + h_c·θ = %.4g m > B/6: contact length c = 3(B/2 − e) = %.4g m, d_max = "
                      "%.4g m, u = (μ kn/ks)·d_max·[1 − √(1 − H/(μW))] (%.3g × H/(ks·A)); mean over the second half after "
                      "the ramp",
                      e, c, wb.peak_penetration(e), u_ref / elastic);
    else
        std::snprintf(why, sizeof why,
                      "Winkler block, e = H·h/W + h_c·θ = %.4g m ≤ B/6: the whole base holds%s; mean over the second "
                      "half after the ramp",
                      e, u_ref == elastic ? ", u = H/(ks·A)" : ", the heel slips (solved from the shear balance)");
    // the shear springs along the push: the paper's grid, or the overlap's n sub-contacts per
    // element face
    const BlockDef& b = scene.blocks.at(size_t(scene.reference->block));
    int div = 1;
    for (int k = 0; k < 3; ++k)
        if (std::abs((b.orientation * Vec3::Unit(k)).dot(push_direction(scene))) > 0.5) div = contact.divisions[size_t(k)];
    const double cell = scene.contact.scheme == ContactScheme::paper
                            ? std::min(scene.contact.grid_spacing, wb.width / div)
                            : wb.width / (div * scene.contact.subdivision);
    const LoadDef* l = pull(scene);
    const double ramp = l ? l->ramp : 0.0, shear_period = 2.0 * M_PI * std::sqrt(block_mass(scene, scene.reference->block) /
                                                                               (scene.contact.ks * contact_area(scene)));
    const double period = std::max(wb.rocking_period(e, toe_inertia(scene)), shear_period);
    const double shear_ratio = joint_to_block_shear(scene, scene.reference->block);   // ks·h/G
    char not_judged[400] = "";
    // 10 periods: a ramp of duration t_r leaves swings of about T/(π·t_r) of the static answer
    // (a linear oscillator), 3 % at 10 periods, and the lightly pressed points slip on the overshoot
    if (ramp < 10.0 * period)
        std::snprintf(not_judged, sizeof not_judged,
                      "not judged: the load's ramp (%.3g s) is not slow against the block's rocking and shear on its "
                      "springs (period %.3g s; the oracle is quasi-static from 10 periods on)",
                      ramp, period);
    else if (held.ringing > 0.5 * 0.03 * u_ref)
        std::snprintf(not_judged, sizeof not_judged,
                      "not judged: it still rings by ±%.3g m about its drift (a block rocking on part of its base is "
                      "lightly damped by its contact springs), so the mean is not the static state",
                      held.ringing);
    else if (contact.deformable && shear_ratio > kRigidInShear)
        std::snprintf(not_judged, sizeof not_judged,
                      "not judged: the deformable block is compliant in shear against its joints (ks·h/G = %.3g, above "
                      "%.3g): its own shear adds about %.2g %% to its base's, which the rigid block on springs leaves out",
                      shear_ratio, kRigidInShear, 11.0 * shear_ratio);
    else if (c < 3.0 * cell)
        std::snprintf(not_judged, sizeof not_judged,
                      "not judged: the contact zone (%.3g m) spans fewer than three of the contact's shear springs along "
                      "the push (%.3g m apart): the slip of its lightly pressed end is not resolved%s",
                      c, cell, scene.contact.scheme == ContactScheme::paper ? " (a finer grid_spacing resolves it)"
                                                                             : " (a larger contact.subdivision resolves it)");
    if (not_judged[0]) return info("base shear displacement", "m", mean, u_ref, std::string(not_judged) + "; " + why);
    // 3 %: three or more shear springs sample the triangular pressure's slip zone (measured, 0.5 m
    // cube under 0.3 W at its top, c = 0.3 m, overlap n = 4/8/16: −3.1/−1.4/+0.2 % with 2.4/4.8/9.6
    // springs across it; the paper's case (c), c = 0.373 m on its 0.1 m grid: −2.2 %; under 0.45 W,
    // c = 0.073 m, n = 16: +12.5 % with 2.35 across)
    return relative("base shear displacement", "m", mean, u_ref, 0.03, std::string(why) + "; 3 %: three or more of "
                                                                         "the contact's shear springs sample the slip zone");
}

CaseAnalysis analyse_friction(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const int a = scene.reference->block;
    const double m = block_mass(scene, a), g = gravity(scene), H = scene.reference->values.at("force");
    const double T = s.back().t;
    CaseAnalysis r;
    if (scene.reference->kind == "slide") {
        Series x = along_push(scene, s, mass_properties(scene.blocks.at(size_t(a)).corners, 1.0).centre, true);
        r.quantity = "displacement of A's centre of mass along the push, m";
        r.measured = x;
        r.analytic = friction_curve(scene, {}, x.t);
        r.analytic_label = "s = a t²/2, a = (H/W − μ) g";
        const double acc = oracle::pulled_block_acceleration(m, g, H, scene.contact.friction);
        // skip the first 10 % (the shear spring's start-up transient), then fit x = c0 + c1 t + c2 t²
        auto c = polyfit(x, 2, 0.1 * T, T);
        r.metrics.push_back(relative("sliding acceleration", "m/s²", 2.0 * c[2], acc, 0.01,
                                     "(H/W − μ) g, quadratic fit over the last 90 % of the run; 1 %"));
        auto half = crossings(x, 0.5 * 0.5 * acc * T * T, Crossing::up);
        if (!half.empty()) { r.event_time = half[0]; r.has_event = true; }
        return r;
    }
    // from where the scene placed it: a settled start has taken up part of the shear before t = 0
    // when the load acts from t = 0 (docs/dem.md, Settled start)
    const Vec3 local = base_centre(scene);
    Series u = along_push(scene, s, local, false);
    const BlockDef& placed = scene.blocks.at(size_t(a));
    const double x0 = (placed.position + placed.orientation * local).dot(push_direction(scene));
    for (double& y : u.y) y -= x0;
    r.quantity = "displacement of A's base centre along the push, m";
    r.measured = u;
    r.analytic = friction_curve(scene, {}, u.t);
    double h = 0.0;
    const auto wb = winkler(scene, &h);
    const double u_ref = wb.shear_displacement(H, h);
    const double elastic = H / (scene.contact.ks * contact_area(scene));
    r.analytic_label = "quasi-static base shear of a rigid block on a Winkler base (slip where μ·p < ks·u)";
    r.analytic_key = "Winkler block";
    const LoadDef* l = pull(scene);
    const double settled = l ? l->start + l->ramp : 0.0;
    const double peak = std::max(std::abs(max_value(u)), std::abs(min_value(u)));
    r.metrics.push_back(info("largest displacement", "m", peak, NAN, "base shear plus any slip"));
    // holding means no progressive slip once the load is constant: the drift over the second half
    // after the ramp, its ringing (a block rocking on part of its base rings long) taken out
    const double t0 = settled + 0.5 * (T - settled);
    const double scale = std::isfinite(u_ref) ? u_ref : elastic;
    HeldDrift held;
    r.metrics.push_back(slip_while_held(u, t0, T, 0.05 * scale,
                                        "the second half after the ramp; 5 % of the quasi-static base shear " +
                                            message_number(scale, 6) + " m",
                                        &held));
    if (contact.penalty) r.metrics.push_back(base_shear_metric(scene, wb, h, u_ref, u, t0, T, held, contact));
    return r;
}

}  // namespace

// kinds "slide" and "stick" (c): Coulomb's law holds for rigid contact; the engines' matched
// springs have no elastic stick
static const CaseKind& slide_kind() {
    static const FunctionKind k("slide", {"force"}, analyse_friction, friction_curve, rigid_contact_only,
                                "slid half the reference distance", check_friction);
    return k;
}

static const CaseKind& stick_kind() {
    static const FunctionKind k("stick", {"force"}, analyse_friction, friction_curve, rigid_contact_only,
                                "none (the block holds)", check_friction);
    return k;
}

namespace {
const KindRegistration slide_registered(slide_kind);
const KindRegistration stick_registered(stick_kind);
}  // namespace

}  // namespace cairn::cases
