// a block on a plane base, level or inclined, driven along it by its loads (a ground motion's
// −m·a_g among them) and by gravity's part along the plane: Newmark's rigid sliding block, which
// holds while the drive is inside the friction disk μ·n
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "analytic/newmark.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "output/number_format.hpp"

namespace cairn::cases {

namespace {

double rocking_ratio(const Scene& scene);
void check_drive(const Scene& scene);

/// the face of the base (the first fixed block) the block rests on: its outward unit normal n and
/// two unit directions t1, t2 = n × t1 in it (world x and y on a level base under gravity along −z)
struct Base {
    Vec3 n, t1, t2;
};

Base base_plane(const Scene& scene) {
    for (const auto& b : scene.blocks) {
        if (!b.fixed) continue;
        Base p;
        p.n = b.orientation * Vec3::UnitZ();
        // the plane must face up, against gravity (an incline flatter than 89.9°)
        if (!(scene.gravity.dot(p.n) < -std::cos(1.57) * scene.gravity.norm()))
            throw Error(scene.source + ": reference.kind = \"newmark\": the side of block '" + b.name +
                        "' that the block rests on must face up against gravity, as a base; it is at " +
                        message_number(std::acos(std::clamp(-scene.gravity.normalized().dot(p.n), -1.0, 1.0))) +
                        " rad to the upward vertical");
        Vec3 t1 = Vec3::UnitX() - Vec3::UnitX().dot(p.n) * p.n;
        if (t1.norm() < 1e-6) t1 = Vec3::UnitY() - Vec3::UnitY().dot(p.n) * p.n;
        p.t1 = t1.normalized();
        p.t2 = p.n.cross(p.t1);
        return p;
    }
    throw Error(scene.source + ": reference.kind = \"newmark\" needs a fixed block as its base");
}

/// gravity and the loads per unit mass (m/s²) in the base's frame: (along t1, along t2, along n);
/// the base presses with −(along n)
std::function<Vec3(double)> plane_drive(const Scene& scene) {
    const Base p = base_plane(scene);
    const auto loads = reference_drive(scene);
    const Vec3 g = scene.gravity;
    return [p, loads, g](double t) {
        const Vec3 f = g + loads(t);
        return Vec3(f.dot(p.t1), f.dot(p.t2), f.dot(p.n));
    };
}

/// refuses what Newmark's block leaves out: a base facing down, a spin or a speed off the base at release
void check_newmark(const Scene& scene) {
    const Base p = base_plane(scene);
    const BlockDef& d = scene.blocks.at(size_t(scene.reference->block));
    // 1e-3 of the speed: a launch typed to 3-4 digits is along the base (as a plane's angle, 1e-3 rad)
    const double off = std::abs(d.velocity.dot(p.n));
    if (d.angular_velocity.norm() > 0.0 || off > 1e-3 * d.velocity.norm())
        throw Error(scene.source + ": reference.kind = \"newmark\": blocks." + d.name +
                    ".velocity/angular_velocity: Newmark's block is launched along the base only (no spin, no speed "
                    "off the base's plane; its normal is " + message_vector(p.n) + ", the speed along it " +
                    message_number(off) + " m/s)");
    if (d.velocity.norm() > 0.0 && scene.contact.friction > rocking_ratio(scene))
        throw Error(scene.source + ": blocks." + d.name + ".velocity: launched with μ = " + message_number(scene.contact.friction) +
                    " above its b/h = " + message_number(rocking_ratio(scene)) +
                    ", the block tips over its leading edge as friction stops it, which Newmark's block does not model");
}

/// the oracle's run over the scene's duration, launched at the block's initial velocity
oracle::SlidingHistory oracle_run(const Scene& scene) {
    check_newmark(scene);
    const Base p = base_plane(scene);
    const Vec3 v0 = scene.blocks.at(size_t(scene.reference->block)).velocity;
    // in the base's frame, gravity is part of the drive: the oracle's own gravity is 0
    return oracle::newmark_slide(plane_drive(scene), 0.0, scene.contact.friction, scene.run.duration,
                                 Vec2(v0.dot(p.t1), v0.dot(p.t2)));
}

/// the largest drive along the base per unit mass (m/s², gravity's part included) and its unit
/// direction in the base's frame (t1 when there is none), sampled every 10 steps of the oracle's grid
struct LargestDrive {
    double size = 0.0;
    Vec2 dir = Vec2::UnitX();
};

LargestDrive largest_drive(const Scene& scene, const oracle::SlidingHistory& h) {
    const auto f = plane_drive(scene);
    LargestDrive out;
    for (size_t i = 0; i < h.t.size(); i += 10) {
        const Vec3 d = f(h.t[i]);
        const Vec2 fh(d.x(), d.y());
        if (fh.norm() > out.size) out.size = fh.norm(), out.dir = fh.normalized();
    }
    return out;
}

/// the unit direction in the base's frame the block is judged along: that of the oracle's final
/// slide, or of the largest drive when it holds
Vec2 judged_direction(const oracle::SlidingHistory& h, const LargestDrive& largest) {
    const Vec2 end = h.x.back();
    return end.norm() > 0.0 ? Vec2(end.normalized()) : largest.dir;
}

/// the reference block's centre of mass moved along `e` since the first sample, m
metrics::Series along(const Scene& scene, const std::vector<Sample>& s, const Vec3& e) {
    const int f = free_index(scene, scene.reference->block);
    metrics::Series out{times(s), {}};
    for (const auto& x : s) out.y.push_back((x.blocks.at(f).position - s.front().blocks.at(f).position).dot(e));
    return out;
}

/// the reference block's material point `local` (block frame) moved along `e` since the first sample, m
metrics::Series along_point(const Scene& scene, const std::vector<Sample>& s, const Vec3& e, const Vec3& local) {
    const int f = free_index(scene, scene.reference->block);
    const Vec3 r = local - mass_properties(scene.blocks.at(size_t(scene.reference->block)).corners, 1.0).centre;
    metrics::Series out{times(s), {}};
    const BlockState& b0 = s.front().blocks.at(size_t(f));
    const Vec3 x0 = b0.position + b0.orientation * r;
    for (const auto& x : s) {
        const BlockState& b = x.blocks.at(size_t(f));
        out.y.push_back((b.position + b.orientation * r - x0).dot(e));
    }
    return out;
}

/// the oracle's displacement along `e` (in the base's frame) at the times `t`, m
std::vector<double> along_oracle(const oracle::SlidingHistory& h, const Vec2& e, const std::vector<double>& t) {
    std::vector<double> out;
    for (double x : t) out.push_back(h.at(x).dot(e));
    return out;
}

std::vector<double> newmark_curve(const Scene& scene, ContactKind, const std::vector<double>& t) {
    const auto h = oracle_run(scene);
    return along_oracle(h, judged_direction(h, largest_drive(scene, h)), t);
}

/// the block's footing on the base, block frame: k its height axis (the frame axis nearest the
/// base's normal, so a block laid on its side is measured as it lies), its half-widths across the
/// height from the centre of mass (the nearer side each way), the height of the centre of mass above
/// its lowest side, and the point of that side under the centre of mass
struct Footing {
    int k = 2;
    Vec3 half = Vec3::Zero();   // m, along the frame axes (the height axis's entry unused)
    double height = 0.0;        // m
    Vec3 base = Vec3::Zero();   // m, block frame
    std::array<Vec2, 3> axes;   // the frame axes in the base's frame (t1, t2)
};

Footing footing(const Scene& scene) {
    const BlockDef& d = scene.blocks.at(size_t(scene.reference->block));
    const Base p = base_plane(scene);
    const Vec3 up = d.orientation.inverse() * p.n;   // the base's normal in the block frame
    Footing f;
    f.k = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(up[i]) > std::abs(up[f.k])) f.k = i;
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const auto& c : d.corners) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
    const Vec3 centre = mass_properties(d.corners, 1.0).centre;
    for (int i = 0; i < 3; ++i) f.half[i] = std::min(centre[i] - lo[i], hi[i] - centre[i]);
    f.height = up[f.k] > 0.0 ? centre[f.k] - lo[f.k] : hi[f.k] - centre[f.k];
    f.base = centre;
    f.base[f.k] = up[f.k] > 0.0 ? lo[f.k] : hi[f.k];
    for (int i = 0; i < 3; ++i) {
        const Vec3 a = d.orientation * Vec3::Unit(i);
        f.axes[size_t(i)] = Vec2(a.dot(p.t1), a.dot(p.t2));
    }
    return f;
}

/// the least of the block's half-widths across its height over the height of its centre of mass:
/// the drive's ratio to n beyond which a rigid block would rock, whichever way it pushes
double rocking_ratio(const Scene& scene) {
    const Footing f = footing(scene);
    double b = 1e300;
    for (int i = 0; i < 3; ++i)
        if (i != f.k) b = std::min(b, f.half[i]);
    return b / f.height;
}

/// the drive's ratio to n beyond which a rigid block rocks when pushed along `u` (unit, in the
/// base's frame): the distance from the centre to the edge the push's line crosses over the
/// height, min(a/|cos φ|, b/|sin φ|)/h for half sides a, b at φ to the push
double rocking_ratio_along(const Footing& f, const Vec2& u) {
    double reach = 1e300;
    for (int i = 0; i < 3; ++i) {
        if (i == f.k) continue;
        const double c = std::abs(u.dot(f.axes[size_t(i)]));
        if (c > 1e-12) reach = std::min(reach, f.half[i] / c);
    }
    return reach / f.height;
}

/// refuses a drive Newmark's block cannot follow: one that lifts the block off its base, or one
/// whose ratio to the base's pressure passes the block's rocking threshold where friction holds it
/// (μ above that threshold: the rigid block rocks, and may fall, before it slides). Sampled at the
/// oracle's step
void check_drive(const Scene& scene) {
    const auto f = plane_drive(scene);
    const Footing foot = footing(scene);
    const double mu = scene.contact.friction, T = scene.run.duration;
    const double h = std::max(1e-5, T / 2e6);
    const long steps = std::max(1L, long(std::ceil(T / h)));
    const std::string key = scene.source + ": reference.kind = \"newmark\": ";
    double worst = 1.0, worst_t = 0.0, worst_ratio = 0.0, worst_tip = 0.0;   // the drive's largest excess over the threshold
    for (long i = 0; i <= steps; ++i) {
        const double t = std::min(T, double(i) * h);
        const Vec3 d = f(t);
        const double n = -d.z();   // the pressure into the base per unit mass, m/s²
        if (!(n > 0.0))
            throw Error(key + "gravity and the loads (a [ground_motion]'s −m·a_g among them) lift the block off its base at t = " +
                        message_number(t, 6) + " s (their part into the base is " + message_number(n) +
                        " m/s²): Newmark's block stays on its base and does not fly");
        const Vec2 fh(d.x(), d.y());
        if (!(fh.norm() > 0.0)) continue;
        const double ratio = fh.norm() / n, tip = rocking_ratio_along(foot, fh.normalized());
        if (mu > tip && ratio / tip > worst) worst = ratio / tip, worst_t = t, worst_ratio = ratio, worst_tip = tip;
    }
    if (worst > 1.0)
        throw Error(key + "the drive along the base reaches " + message_number(worst_ratio) + " of the pressure into it (at t = " +
                    message_number(worst_t, 6) + " s), above the block's rocking threshold b/h = " + message_number(worst_tip) +
                    " that way, and friction (μ = " + message_number(mu) +
                    ") holds the base there: a rigid block rocks, and may overturn, before it slides, which "
                    "Newmark's sliding block does not model (a ground_rocking reference does)");
}

CaseAnalysis judged_newmark(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const auto h = oracle_run(scene);
    const LargestDrive largest = largest_drive(scene, h);
    const Vec2 e2 = judged_direction(h, largest);
    const Base base = base_plane(scene);
    const Vec3 e = e2.x() * base.t1 + e2.y() * base.t2;   // the same direction in the world
    const int a = scene.reference->block;
    const double m = block_mass(scene, a), T = s.back().t;
    CaseAnalysis r;
    r.measured = along(scene, s, e);
    r.quantity = "displacement of A's centre of mass along the base, m";
    r.analytic = along_oracle(h, e2, r.measured.t);
    r.analytic_label = "Newmark's rigid sliding block, friction μ·f_n (μ·(g − f_z) on a level base)";
    r.analytic_key = "Newmark block";
    const double rock = rocking_ratio(scene);
    char basis[400];
    std::snprintf(basis, sizeof basis,
                  "largest |f_t|/f_n of gravity and the loads per unit mass along and into the base (|f_h|/(g − f_z) "
                  "on a level base), against μ; the oracle holds the motion to sliding: it is valid while this stays "
                  "below b/h = %.4g (a rigid block's rocking threshold)", rock);
    r.metrics.push_back(info("friction demand", "-", h.peak_ratio, scene.contact.friction, basis));
    const double slide = h.x.back().norm();
    // the run's largest displacement along e, either way, m
    const double moved_most = std::max(std::abs(max_value(r.measured)), std::abs(min_value(r.measured)));
    const bool springs = contact.penalty && contact.point_springs && scene.contact.ks > 0.0;
    if (slide > 0.0) {
        double peak_ref = 0.0;
        for (const Vec2& x : h.x) peak_ref = std::max(peak_ref, std::abs(x.dot(e2)));
        // a record moves the block both ways and its final place is the difference: both the
        // largest and the final slide are judged on the scale of the largest
        double allowance = 0.01 * peak_ref;
        std::string why = "1 % of the largest slide (the oracle's own error is below 1e-4 of it): the engines' contact "
                          "and step";
        if (springs) {
            // a penalty block moves by its shear springs' stretch (up to μ·m·g/(ks·A)) before it
            // slides, and where the drive jumps faster than the springs follow (J, its change
            // within one period 2π/ω, ω = √(ks·A/m)) it runs ahead at up to J/ω until it stops:
            // (J/ω)·t_slide (measured 1.15–1.2 × on a 0.4 m cube under a 0.8 g step at kn 1e8 and 1e9)
            const double w = std::sqrt(scene.contact.ks * contact_area(scene) / m);
            const double pressed = -scene.gravity.dot(base.n);   // gravity's part into the base, m/s²
            const double stretch = scene.contact.friction * m * pressed / (scene.contact.ks * contact_area(scene));
            const size_t lag = std::max<size_t>(1, size_t(std::lround(2.0 * M_PI / w / (h.t[1] - h.t[0]))));
            const auto f = plane_drive(scene);
            double jump = 0.0;
            for (size_t i = 0; i + lag < h.t.size(); ++i) {
                const Vec3 d0 = f(h.t[i]), d1 = f(h.t[i + lag]);
                jump = std::max(jump, Vec2(d1.x() - d0.x(), d1.y() - d0.y()).norm());
            }
            const double ahead = 2.0 * jump / w * h.slide_time;
            allowance += stretch + ahead;
            char buf[500];
            std::snprintf(buf, sizeof buf,
                          "1 %% of the largest slide, plus the shear springs' stretch μmg/(ks·A) = %.3g m and their "
                          "run-ahead 2·(J/ω)·t_slide = %.3g m (J = %.3g m/s², the drive's largest change within "
                          "2π/ω; ω = √(ks·A/m) = %.4g rad/s; t_slide = %.3g s): a penalty contact converges to the "
                          "rigid block as ks grows",
                          stretch, ahead, jump, w, h.slide_time);
            why = buf;
        }
        r.metrics.push_back(absolute("largest slide", "m", moved_most, peak_ref, allowance, why));
        r.metrics.push_back(absolute("final slide", "m", r.measured.y.back(), h.x.back().dot(e2), allowance, why));
        r.metrics.push_back(info("sliding time", "s", h.slide_time, NAN,
                                 "the oracle's time spent sliding, over " + std::to_string(h.onsets) + " episode(s)"));
        const auto half = crossings(r.measured, 0.5 * slide, Crossing::up);
        if (!half.empty()) r.event_time = half[0], r.has_event = true;
        return r;
    }
    // holds: no progressive slip over the second half of the run, against the elastic base shear
    // of the largest drive
    const double elastic = scene.contact.ks > 0.0 ? m * largest.size / (scene.contact.ks * contact_area(scene)) : 0.0;
    const double scale = elastic > 0.0 ? elastic : 1e-6;
    r.metrics.push_back(info("largest displacement", "m", moved_most, elastic,
                             "elastic base shear m·f/(ks·A) of the largest drive as reference; a load that comes "
                             "suddenly on elastic springs slips once at its onset"));
    // the window: the second half of the run, or where the drive's last change comes later with
    // a tenth of the run left, the second half of the time after it (a record that ends within
    // the second half: the held block rests from then on, once its ringing has died as in the
    // second half of any run; the swings the record forced before are no slip)
    const auto f = plane_drive(scene);
    const Vec3 f_last = f(T);
    double changed = 0.0;   // s: the last time of the oracle's grid where the drive differs from its end
    for (const double t : h.t)
        if ((f(t) - f_last).norm() > 1e-9 * largest.size) changed = t;
    const bool after = changed > 0.5 * T && changed < 0.9 * T;
    const double t0 = after ? 0.5 * (changed + T) : 0.5 * T;
    char why[300];
    std::snprintf(why, sizeof why,
                  "the drive stays inside the friction disk; the base centre over %s; 5 %% of the elastic base "
                  "shear %.3g m, as the stick case",
                  after ? ("the second half of the time after the drive's end at " + message_number(changed) + " s").c_str()
                        : "the second half of the run",
                  scale);
    // at the base (the probe "base" where the scene has one, else the point of its lowest side under
    // the centre of mass): a block still rocking on its springs swings its centre of mass by h·θ
    // over a base that does not slip (a tilt of 1e-6 rad dying out on a 0.5 m cube: 2.4e-7 m)
    const int probe = probe_index(scene, "base");
    const Vec3 at = probe >= 0 && scene.probes.at(size_t(probe)).block == a ? scene.probes.at(size_t(probe)).point
                                                                               : footing(scene).base;
    r.metrics.push_back(slip_while_held(along_point(scene, s, e, at), t0, T, 0.05 * scale, why));
    return r;
}

/// what the kind refuses before any run: another free block touching it, check_newmark's launch, and a
/// drive that lifts or rocks the block
void check_newmark_scene(const Scene& scene) {
    require_alone(scene, "newmark");
    check_newmark(scene);
    check_drive(scene);
}

/// the run judged, a deformable block compliant against its joints shown instead (show_if_flexible)
CaseAnalysis analyse_newmark(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    CaseAnalysis r = judged_newmark(scene, s, contact);
    show_if_flexible(scene, contact, r.metrics);
    return r;
}

}  // namespace

// kind "newmark": Coulomb's law holds for rigid contact
static const CaseKind& newmark_kind() {
    static const FunctionKind k("newmark", {}, analyse_newmark, newmark_curve, rigid_contact_only,
                                "slid half the final distance", check_newmark_scene);
    return k;
}

namespace {
const KindRegistration newmark_registered(newmark_kind);
}  // namespace

}  // namespace cairn::cases
