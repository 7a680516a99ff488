// a block on a horizontal base driven along it by its loads (a ground motion's −m·a_g among them):
// Newmark's rigid sliding block, which holds while the drive is inside the friction disk μ·n
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analytic/newmark.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"

namespace cairn::cases {

namespace {

double rocking_ratio(const Scene& scene);

/// refuses what Newmark's block leaves out: a tilted base, a spin or a vertical speed at release
void check_newmark(const Scene& scene) {
    require_horizontal_base(scene, "newmark");
    const BlockDef& d = scene.blocks.at(size_t(scene.reference->block));
    if (d.angular_velocity.norm() > 0.0 || std::abs(d.velocity.z()) > 1e-9 * std::max(1.0, d.velocity.norm()))
        throw Error(scene.source + ": reference.kind = \"newmark\": blocks." + d.name +
                    ".velocity/angular_velocity: Newmark's block is launched along the base only (no spin, no vertical "
                    "speed)");
    if (d.velocity.norm() > 0.0 && scene.contact.friction > rocking_ratio(scene))
        throw Error(scene.source + ": blocks." + d.name + ".velocity: launched with μ = " + message_number(scene.contact.friction) +
                    " above its b/h = " + message_number(rocking_ratio(scene)) +
                    ", the block tips over its leading edge as friction stops it, which Newmark's block does not model");
}

/// the oracle's run over the scene's duration, launched at the block's initial velocity
oracle::SlidingHistory oracle_run(const Scene& scene) {
    check_newmark(scene);
    const Vec3 v0 = scene.blocks.at(size_t(scene.reference->block)).velocity;
    return oracle::newmark_slide(reference_drive(scene), gravity(scene), scene.contact.friction, scene.run.duration,
                                 Vec2(v0.x(), v0.y()));
}

/// the largest horizontal drive per unit mass (m/s²) and its unit direction (x when there is none),
/// sampled every 10 steps of the oracle's grid
struct LargestDrive {
    double size = 0.0;
    Vec2 dir = Vec2::UnitX();
};

LargestDrive largest_drive(const Scene& scene, const oracle::SlidingHistory& h) {
    const auto f = reference_drive(scene);
    LargestDrive out;
    for (size_t i = 0; i < h.t.size(); i += 10) {
        const Vec3 d = f(h.t[i]);
        const Vec2 fh(d.x(), d.y());
        if (fh.norm() > out.size) out.size = fh.norm(), out.dir = fh.normalized();
    }
    return out;
}

/// the horizontal unit direction the block is judged along: that of the oracle's final slide, or
/// of the largest drive when it holds
Vec3 judged_direction(const oracle::SlidingHistory& h, const LargestDrive& largest) {
    const Vec2 end = h.x.back();
    const Vec2 dir = end.norm() > 0.0 ? Vec2(end.normalized()) : largest.dir;
    return Vec3(dir.x(), dir.y(), 0.0);
}

/// the reference block's centre of mass moved along `e` since the first sample, m
metrics::Series along(const Scene& scene, const std::vector<Sample>& s, const Vec3& e) {
    const int f = free_index(scene, scene.reference->block);
    metrics::Series out{times(s), {}};
    for (const auto& x : s) out.y.push_back((x.blocks.at(f).position - s.front().blocks.at(f).position).dot(e));
    return out;
}

/// the oracle's displacement along `e` at the times `t`, m
std::vector<double> along_oracle(const oracle::SlidingHistory& h, const Vec3& e, const std::vector<double>& t) {
    std::vector<double> out;
    for (double x : t) out.push_back(h.at(x).dot(Vec2(e.x(), e.y())));
    return out;
}

std::vector<double> newmark_curve(const Scene& scene, ContactKind, const std::vector<double>& t) {
    const auto h = oracle_run(scene);
    return along_oracle(h, judged_direction(h, largest_drive(scene, h)), t);
}

/// the least of the block's half-widths along x and y over the height of its centre of mass above
/// its lowest corner (block frame): the drive's ratio to n beyond which a rigid block would rock
double rocking_ratio(const Scene& scene) {
    const BlockDef& d = scene.blocks.at(size_t(scene.reference->block));
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const auto& c : d.corners) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
    const Vec3 centre = mass_properties(d.corners, 1.0).centre;
    const double b = std::min(std::min(centre.x() - lo.x(), hi.x() - centre.x()), std::min(centre.y() - lo.y(), hi.y() - centre.y()));
    return b / (centre.z() - lo.z());
}

CaseAnalysis analyse_newmark(const Scene& scene, const std::vector<Sample>& s, ContactKind contact) {
    using namespace metrics;
    const auto h = oracle_run(scene);
    const LargestDrive largest = largest_drive(scene, h);
    const Vec3 e = judged_direction(h, largest);
    const int a = scene.reference->block;
    const double m = block_mass(scene, a), T = s.back().t;
    CaseAnalysis r;
    r.measured = along(scene, s, e);
    r.quantity = "displacement of A's centre of mass along the base, m";
    r.analytic = along_oracle(h, e, r.measured.t);
    r.analytic_label = "Newmark's rigid sliding block, μ·(g − f_z)";
    r.analytic_key = "Newmark block";
    const double rock = rocking_ratio(scene);
    char basis[300];
    std::snprintf(basis, sizeof basis,
                  "largest |f_h|/(g − f_z) of the loads per unit mass, against μ; the oracle holds the motion to "
                  "sliding: it is valid while this stays below b/h = %.4g (a rigid block's rocking threshold)", rock);
    r.metrics.push_back(info("friction demand", "-", h.peak_ratio, scene.contact.friction, basis));
    const double slide = h.x.back().norm();
    // the run's largest displacement along e, either way, m
    const double moved_most = std::max(std::abs(max_value(r.measured)), std::abs(min_value(r.measured)));
    const bool springs = contact.penalty && contact.point_springs && scene.contact.ks > 0.0;
    if (slide > 0.0) {
        const Vec2 e2(e.x(), e.y());
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
            const double stretch = scene.contact.friction * m * gravity(scene) / (scene.contact.ks * contact_area(scene));
            const size_t lag = std::max<size_t>(1, size_t(std::lround(2.0 * M_PI / w / (h.t[1] - h.t[0]))));
            const auto f = reference_drive(scene);
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
    char why[300];
    std::snprintf(why, sizeof why,
                  "the drive stays inside the friction disk; the second half of the run; 5 %% of the elastic base "
                  "shear %.3g m, as the stick case", scale);
    r.metrics.push_back(slip_while_held(r.measured, 0.5 * T, T, 0.05 * scale, why));
    return r;
}

}  // namespace

// kind "newmark": Coulomb's law holds for rigid contact
static const CaseKind& newmark_kind() {
    static const FunctionKind k("newmark", {}, analyse_newmark, newmark_curve, rigid_contact_only,
                                "slid half the final distance", check_newmark);
    return k;
}

namespace {
const KindRegistration newmark_registered(newmark_kind);
}  // namespace

}  // namespace cairn::cases
