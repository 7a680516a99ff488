// generated arch, wall and column (the builders behind `cairn make`) pass the scene loader's checks
// and stand under gravity on dem and Bullet: total mass and centre of mass against closed forms,
// every bearing interface in contact, and every block's displacement within the elastic settlement
// of the joints under it; the arch's settled crown against the statics of its no-tension joints
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <map>
#include <utility>

#include <Eigen/Dense>

#include "engine_scenes.hpp"
#include "geometry/hexahedron.hpp"
#include "geometry/overlap.hpp"
#include "registry.hpp"
#include "scene/arch_builder.hpp"
#include "scene/column_builder.hpp"
#include "scene/scene_io.hpp"
#include "scene/scene_toml.hpp"
#include "scene/wall_builder.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

constexpr double kRho = 2600.0;   // kg/m³, base_scene's stone
constexpr double kG = 9.81;       // m/s²
constexpr double kKn = 1e9;       // N/m³, the `cairn make` default

struct Generated {
    std::string label;
    Scene scene;                             // as the loader returns it
    double mass = 0.0;                       // closed form, kg
    Vec3 centre = Vec3::Zero();              // closed form, m
    std::set<std::pair<int, int>> bearing;   // block index pairs that carry weight (lower first)
    double bound = 0.0;                      // largest allowed displacement of any block, m
};

// the scene as `cairn make` gives it, written as TOML and read back through the loader
Scene through_loader(Scene s) {
    s.contact.kn = s.contact.ks = kKn;
    s.contact.friction = 0.7;
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.1;
    s.run.duration = 0.3;
    return parse_scene(scene_toml(s, "generated in a test"), "<generated " + s.name + ">");
}

int index_of(const Scene& s, const std::string& name) {
    for (size_t i = 0; i < s.blocks.size(); ++i)
        if (s.blocks[i].name == name) return int(i);
    FAIL("no block " << name);
    return -1;
}

std::pair<int, int> pair_of(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// the static closure of the top joint of a stack of n layers of height h under its own weight,
// summed over the joints below: Σ_{j=1..n} ρ g h (n − j + 1) / kn = ρ g h n(n + 1) / (2 kn). The
// blocks start touching with no overlap, so they drop onto the springs as a step load: a linear
// spring loaded suddenly peaks at twice its static closure; ×1.5 more for the higher modes of the
// stack and the uneven bed pressure where running bond overlaps and the stack's ends
double stack_bound(int n, double h) { return 2.0 * 1.5 * kRho * kG * h * n * (n + 1) / (2.0 * kKn); }

Generated column() {
    ColumnSpec c{3, 0.3, 0.5, true};
    Scene s = base_scene("column");
    add_column(s, c);
    Generated g;
    g.label = s.name;
    g.scene = through_loader(s);
    g.mass = kRho * c.drums * c.width * c.width * c.drum_height;
    g.centre = Vec3(0, 0, 0.5 * c.drums * c.drum_height);   // the slab's top is z = 0
    g.bearing = {pair_of(index_of(g.scene, "base"), index_of(g.scene, "D1")),
                 pair_of(index_of(g.scene, "D1"), index_of(g.scene, "D2")),
                 pair_of(index_of(g.scene, "D2"), index_of(g.scene, "D3"))};
    g.bound = stack_bound(c.drums, c.drum_height);
    return g;
}

Generated wall() {
    WallSpec w;
    w.courses = 4;
    w.bricks = 4;
    Scene s = base_scene("wall");
    add_wall(s, w);
    Generated g;
    g.label = s.name;
    g.scene = through_loader(s);
    const double l = w.brick.x(), t = w.brick.y(), h = w.brick.z();
    // half bricks at the ends of odd courses: every course is bricks·l long, the wall a full box
    g.mass = kRho * w.courses * w.bricks * l * t * h;
    g.centre = Vec3(0, 0, 0.5 * w.courses * h);
    // bed joints: each brick bears on the slab (course 0) or on the bricks of the course below whose
    // extents along x overlap its own by a positive length
    // the loader keeps blocks in name order: brick i of course c is b<c>_<i>, zero-padded
    auto brick = [&](int c, size_t i) {
        char name[48];
        std::snprintf(name, sizeof name, "b%03d_%03zu", c, i);
        return index_of(g.scene, name);
    };
    std::vector<std::vector<std::pair<double, double>>> spans;
    for (int c = 0; c < w.courses; ++c) {
        double x = -0.5 * l * w.bricks;
        spans.emplace_back();
        for (double len : wall_course(w, c)) {
            spans.back().push_back({x, x + len});
            x += len;
        }
    }
    const int base = index_of(g.scene, "base");
    for (size_t i = 0; i < spans[0].size(); ++i) g.bearing.insert(pair_of(base, brick(0, i)));
    for (int c = 1; c < w.courses; ++c)
        for (size_t i = 0; i < spans[size_t(c)].size(); ++i)
            for (size_t j = 0; j < spans[size_t(c) - 1].size(); ++j) {
                const auto& up = spans[size_t(c)][i];
                const auto& down = spans[size_t(c) - 1][j];
                if (std::min(up.second, down.second) - std::max(up.first, down.first) > 1e-9)
                    g.bearing.insert(pair_of(brick(c, i), brick(c - 1, j)));
            }
    g.bound = stack_bound(w.courses, h);
    return g;
}

Generated arch() {
    ArchSpec a{9, 2.25, 0.5, 0.5, M_PI};   // `cairn make arch`'s defaults: t/R = 0.22, well above the
                                           // least thickness of a semicircular arch (≈ 0.107 R)
    Scene s = base_scene("arch");
    add_arch(s, a);
    Generated g;
    g.label = s.name;
    g.scene = through_loader(s);
    const double r1 = a.radius - 0.5 * a.thickness, r2 = a.radius + 0.5 * a.thickness;
    const double phi = a.angle / a.voussoirs;   // angle of one voussoir
    // voussoirs have straight chords between corners on the two circles: each is the difference of
    // two triangles with their apex at the centre, area ½ r² sin φ, centroid (2/3) r cos(φ/2) out
    // along the voussoir's bisector
    g.mass = kRho * a.depth * a.voussoirs * 0.5 * std::sin(phi) * (r2 * r2 - r1 * r1);
    // the bisectors' heights average Σ sin((i + ½)φ)/N = 1/(N sin(φ/2)) for a semicircle
    const double arm = 2.0 / 3.0 * std::cos(0.5 * phi) * (r2 * r2 * r2 - r1 * r1 * r1) / (r2 * r2 - r1 * r1);
    g.centre = Vec3(0, 0, arm / (a.voussoirs * std::sin(0.5 * phi)));
    const int left = index_of(g.scene, "left"), right = index_of(g.scene, "right"), v1 = index_of(g.scene, "V1");
    g.bearing.insert(pair_of(left, v1));
    for (int i = 0; i + 1 < a.voussoirs; ++i) g.bearing.insert(pair_of(v1 + i, v1 + i + 1));
    g.bearing.insert(pair_of(v1 + a.voussoirs - 1, right));
    // no bound: the arch's rest is its joints' statics (arch_rest), checked in its own tests
    return g;
}


// The arch at rest on its joints, as linear statics of the same discrete model: rigid voussoirs
// (3 degrees of freedom each in the x-z plane: ux, uz and the rotation θ about y, at the centroid)
// joined by the joints' penalty springs kn and ks per area, integrated over each joint face
// t × depth with the given points across t (s from the joint's centre along the radius, weight m).
// The energy ½ Σ_joints depth·Σ_points w·(kn (Δ·τ)² + ks (Δ·ρ)²), Δ the jump in displacement at the
// point, τ the joint normal (the arch's tangent) and ρ its radius, is exact for a closed joint (linear
// pressure): it holds while every joint stays compressed over its whole face, which the solution
// reports (least edge closure). The settled arch of an engine that integrates its joints this way
// rests here: the joints' closure *and* their rotation under the eccentric thrust are in it.
struct ArchRest {
    double crown = 0.0;          // downward displacement of the keystone's centroid, m
    double worst = 0.0;          // largest displacement of any voussoir's centroid, m
    double open_fraction = 0.0;  // fraction of the joints' faces that opened
    double omega = 0.0;          // lowest natural frequency about that state, rad/s
};

struct JointRule {
    std::vector<std::pair<double, double>> points;   // (s / t, weight / t) across the thickness
    double ks_factor = 1.0;                          // shear springs ks × this
};

// exact for any pressure linear across t: two Gauss points
// the midpoint rule on m strips across t: a partly open joint integrated to O(1/m²)
JointRule strips(int m, double ks_factor = 1.0) {
    JointRule r;
    for (int k = 0; k < m; ++k) r.points.push_back({-0.5 + (k + 0.5) / m, 1.0 / m});
    r.ks_factor = ks_factor;
    return r;
}

ArchRest arch_rest(const Scene& s, const ArchSpec& a, const JointRule& rule) {
    const int n = a.voussoirs;
    const double phi = a.angle / n, t = a.thickness, kn = s.contact.kn, ks = s.contact.ks * rule.ks_factor;
    std::vector<Vec3> g(static_cast<size_t>(n));
    Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * n);
    for (int i = 0; i < n; ++i) {
        const BlockDef& b = s.blocks[size_t(index_of(s, "V" + std::to_string(i + 1)))];
        const MassProperties mp =
            mass_properties(placed_corners(b.corners, b.position, b.orientation), s.materials[size_t(b.material)].density);
        g[size_t(i)] = mp.centre;
        mass(3 * i, 3 * i) = mass(3 * i + 1, 3 * i + 1) = mp.mass;
        mass(3 * i + 2, 3 * i + 2) = mp.inertia(1, 1);
        f(3 * i + 1) = -mp.mass * kG;
    }
    // displacement (x, z) at world point p of voussoir k per unit of its 3 freedoms
    auto basis = [&](int k, const Vec3& p) {
        Eigen::Matrix<double, 2, 3> B;
        const Vec3 r = p - g[size_t(k)];
        B << 1, 0, r.z(), 0, 1, -r.x();
        return B;
    };
    // the jump Δ = u_b − u_a at point p of joint j per unit freedom (voussoirs j − 1 and j; the
    // abutments are fixed), the joint's normal τ (the tangent) and radius ρ
    struct JointPoint {
        Eigen::MatrixXd J;
        Eigen::Vector2d tau, rho;
        double weight = 0.0;   // depth × tributary length, m²
    };
    std::vector<JointPoint> pts;
    for (int j = 0; j <= n; ++j) {
        const double al = j * phi + 0.5 * (M_PI - a.angle);
        const Vec3 c(-a.radius * std::cos(al), 0, a.radius * std::sin(al));
        const Eigen::Vector2d tau(std::sin(al), std::cos(al)), rho(-std::cos(al), std::sin(al));
        for (const auto& [sr, wr] : rule.points) {
            const Vec3 p = c + sr * t * Vec3(rho.x(), 0, rho.y());
            Eigen::MatrixXd J = Eigen::MatrixXd::Zero(2, 3 * n);
            if (j > 0) J.block(0, 3 * (j - 1), 2, 3) = -basis(j - 1, p);
            if (j < n) J.block(0, 3 * j, 2, 3) = basis(j, p);
            pts.push_back({J, tau, rho, a.depth * wr * t});
        }
    }
    // no tension: a point carries kn and ks only while its side of the joint is closed. The law is
    // piecewise linear, so the active set is iterated to a fixed point (Newton on each piece)
    std::vector<char> active(pts.size(), 1);
    Eigen::VectorXd q = Eigen::VectorXd::Zero(3 * n);
    Eigen::MatrixXd K;
    for (int it = 0; it < 100; ++it) {
        K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
        for (size_t k = 0; k < pts.size(); ++k)
            if (active[k]) {
                const Eigen::Matrix2d D = kn * pts[k].tau * pts[k].tau.transpose() + ks * pts[k].rho * pts[k].rho.transpose();
                K += pts[k].weight * pts[k].J.transpose() * D * pts[k].J;
            }
        q = K.ldlt().solve(f);
        bool changed = false;
        for (size_t k = 0; k < pts.size(); ++k) {
            const char now = (pts[k].J * q).dot(pts[k].tau) < 0.0;   // closing: the jump points back along τ
            changed |= now != active[k];
            active[k] = now;
        }
        if (!changed) break;
        REQUIRE(it < 99);
    }
    int open = 0;
    for (char x : active) open += !x;
    ArchRest out;
    const int key = n / 2;   // the keystone (odd N) or the voussoir left of the crown joint
    out.crown = -q(3 * key + 1);
    for (int i = 0; i < n; ++i) out.worst = std::max(out.worst, std::hypot(q(3 * i), q(3 * i + 1)));
    out.open_fraction = double(open) / double(pts.size());
    // lowest mode of K x = ω² M x
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(K, mass);
    out.omega = std::sqrt(modes.eigenvalues()(0));
    return out;
}

// what a run ended with: the downward displacement of one free block's centre and the fastest block
struct End {
    double settlement = 0.0;   // m
    double speed = 0.0;        // m/s
    double worst = 0.0;        // largest displacement of any block, m
};

// mass, centre of mass, the loaded bearing joints, and (bound > 0) every block within the bound
// after `duration`; `watched` the index among the free blocks whose settlement is returned
End check_stands(const Generated& g, const std::string& engine, double duration = 0.3, size_t watched = 0) {
    const Scene& s = g.scene;
    CAPTURE(g.label, engine);
    // the loader's mass per block (exact for hexahedra) against the closed form
    double mass = 0.0;
    std::vector<double> masses;
    for (const auto& b : s.blocks)
        if (!b.fixed) {
            masses.push_back(mass_properties(b.corners, s.materials[size_t(b.material)].density).mass);
            mass += masses.back();
        }
    // exact up to the rounding of the corners the scene writer prints (as the builder tests)
    CHECK(mass == Approx(g.mass).epsilon(1e-8));

    auto backend = make_backend(engine);
    RunOptions options;
    options.contact_mode = "matched";   // Bullet with the scene's kn·A, so both settle elastically
    options.record_contacts = true;
    backend->build(s, options);
    Sample start = backend->sample();
    REQUIRE(start.blocks.size() == masses.size());
    Vec3 centre = Vec3::Zero();
    for (size_t i = 0; i < masses.size(); ++i) centre += masses[i] * start.blocks[i].position;
    centre /= mass;
    CAPTURE(centre.transpose(), g.centre.transpose());
    CHECK((centre - g.centre).norm() < 1e-9);   // positions of metres: rounding only

    const int steps = int(std::lround(duration / backend->time_step()));
    for (int i = 0; i < steps; ++i)
        if (backend->step() != StepStatus::ok) FAIL(engine << " unstable: " << backend->failure());
    const Sample end = backend->sample();
    CHECK(end.contacts > 0);
    // every bearing interface carries a normal force
    std::set<std::pair<int, int>> loaded;
    for (const auto& c : backend->contact_points())
        if (c.normal_force.norm() > 0.0 && c.block_a >= 0 && c.block_b >= 0) loaded.insert(pair_of(c.block_a, c.block_b));
    for (const auto& p : g.bearing) {
        CAPTURE(s.blocks[size_t(p.first)].name, s.blocks[size_t(p.second)].name);
        CHECK(loaded.count(p) == 1);
    }
    double worst = 0.0;
    for (size_t i = 0; i < masses.size(); ++i)
        worst = std::max(worst, (end.blocks[i].position - start.blocks[i].position).norm());
    CAPTURE(worst, g.bound);
    WARN(g.label << " on " << engine << ": " << loaded.size() << " loaded pairs (" << g.bearing.size()
                << " bearing), largest displacement " << worst << " m, bound " << g.bound << " m");
    if (g.bound > 0.0) CHECK(worst < g.bound);
    End out;
    out.worst = worst;
    out.settlement = start.blocks[watched].position.z() - end.blocks[watched].position.z();
    for (const auto& b : end.blocks) out.speed = std::max(out.speed, b.velocity.norm());
    return out;
}

// the generated arch settled on `engine` (once per engine: the runs take seconds)
struct Settled {
    Scene scene;
    ArchSpec spec;
    double crown = 0.0;   // downward displacement of the keystone's centre, m
    double speed = 0.0;   // fastest block at the end, m/s
    double worst = 0.0;   // largest displacement of any block, m
};

const Settled& settle_arch(const std::string& engine) {
    static std::map<std::string, Settled> done;
    if (done.count(engine)) return done.at(engine);
    Generated g = arch();
    Settled r;
    r.spec = ArchSpec{9, 2.25, 0.5, 0.5, M_PI};
    const ArchRest rest = arch_rest(g.scene, r.spec, strips(200));
    g.scene.damping.alpha = 2.0 * rest.omega;   // 1/s: the lowest mode critically damped
    // the keystone V5 among the free blocks (the loader keeps name order: left, right are fixed)
    size_t key = 0;
    for (const auto& b : g.scene.blocks) {
        if (b.name == "V5") break;
        if (!b.fixed) ++key;
    }
    const End e = check_stands(g, engine, 0.5, key);
    r.scene = g.scene;
    r.crown = e.settlement;
    r.speed = e.speed;
    r.worst = e.worst;
    return done[engine] = r;
}

}  // namespace

namespace {

bool built_in(const std::string& engine) {
    const auto names = all_backend_names();
    if (std::find(names.begin(), names.end(), engine) != names.end()) return true;
    WARN(engine << " is not built into this binary");
    return false;
}

}  // namespace

TEST_CASE("generated column and wall stand on dem and bullet", "[engines][generated]") {
    const std::string engine = GENERATE(as<std::string>{}, "dem", "bullet");
    if (!built_in(engine)) return;
    SECTION("column of 3 drums") { check_stands(column(), engine); }
    SECTION("running-bond wall of 4 courses") { check_stands(wall(), engine); }
}

// The arch settles onto its joints and rests where the statics of its no-tension joints put it
// (arch_rest). Mass-proportional damping α = 2ω₁ (ω₁ the arch's lowest frequency on its joints)
// brings it to rest within the run without moving that rest: the static equilibrium holds whatever
// α. Mass, centre of mass and the loaded joints are checked as for the column and the wall.
// dem's paper scheme integrates each joint with hitting points on a grid ≤ 0.1 m (trapezoid rule,
// docs/dem.md): its settlement lies between the rest with that rule (6 points across t) and the
// exact integral, widened by 3 % for the motion left after 0.5 s (e^{−αt/2} < 1e-4 of it) and the
// hitting points' activity allowance of 1e-4 of an edge
TEST_CASE("a generated arch rests where the statics of its no-tension joints put it, on dem", "[engines][generated]") {
    const Settled& r = settle_arch("dem");
    const ArchRest exact = arch_rest(r.scene, r.spec, strips(200));
    JointRule grid;   // the paper scheme's hitting points across t = 0.5 m, 0.1 m apart, trapezoid weights
    for (int k = 0; k <= 5; ++k) grid.points.push_back({-0.5 + 0.2 * k, (k == 0 || k == 5) ? 0.1 : 0.2});
    const ArchRest paper = arch_rest(r.scene, r.spec, grid);
    WARN("arch on dem: crown settles " << r.crown << " m; rest with exact joints " << exact.crown << " m ("
         << 100 * exact.open_fraction << " % of the joint faces open), with the hitting points' rule " << paper.crown
         << " m; fastest block at the end " << r.speed << " m/s (omega1 " << exact.omega << " rad/s)");
    CHECK(r.crown > 0.97 * paper.crown);
    CHECK(r.crown < 1.03 * exact.crown);
    // at rest: the motion the step load started, ω₁·δ, has decayed below 1 %
    CHECK(r.speed < 0.01 * exact.omega * exact.crown);
}

// Bullet's matched mode puts kn·A/4 on each point of a pair's contact manifold (A the smaller
// of the two faces that bear the joint: 0.25 m² here, before 0.347 m², the intrados), which stands for a face when the points are its 4 corners. On the arch's inclined
// joints Bullet keeps 2 to 4 points wherever recent frames found them (the crown joint: 2 points on
// its extrados edge, a hinge line), so its joints have neither kn·A nor a face's moment. Undamped
// its crown sinks 6 mm, 7x the joints' statics, and keeps jittering; with α = 2ω₁ as here it ended
// 0.3 mm above its start with the rigid mode's 1e-3 m margin (a hull's lies outside its corners, so
// touching joints began compressed), and settles 0.45 mm of the statics' 0.83 mm with the matched
// mode's 1e-5 m (docs/backends.md, "Matched springs and the margin"). It stands; it does not come to rest: since each joint springs over its
// own joint face (0.25 m², before over the voussoir's face 0, the 0.347 m² intrados) the fastest
// block ends at 5.5e-4 m/s against the 3.6e-4 of 1 % of ω₁·δ (3.4e-4 with the wrong area), the
// velocity-level solver's jitter decaying only about 3× a second with spikes to 1e-3 m/s. The
// settlement and the rest are checked against the statics and reported while they miss
TEST_CASE("a generated arch stands on bullet", "[engines][generated]") {
    if (!built_in("bullet")) return;
    const Settled& r = settle_arch("bullet");
    const ArchRest exact = arch_rest(r.scene, r.spec, strips(200));
    WARN("arch on bullet (matched): crown settles " << r.crown << " m, rest of the joints' statics " << exact.crown
         << " m; largest displacement " << r.worst << " m; fastest block at the end " << r.speed << " m/s");
    // stands: as the arch reference (compare/cases/arch.cpp) judges it, within 5 % of the thickness
    CHECK(r.worst < 0.05 * r.spec.thickness);
}

TEST_CASE("bullet's arch settles as the statics of its joints and comes to rest", "[engines][generated][!mayfail]") {
    if (!built_in("bullet")) return;
    const Settled& r = settle_arch("bullet");
    const ArchRest exact = arch_rest(r.scene, r.spec, strips(200));
    // the misses, see above: without damping the crown sinks 6 mm (and jitters); with α = 2ω₁ it
    // rises; and its blocks keep jittering at the end
    CHECK(std::abs(r.crown - exact.crown) < 0.1 * exact.crown);
    CHECK(r.speed < 0.01 * exact.omega * exact.crown);
}
