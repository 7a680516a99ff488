// the backends against analytic solutions, one test body each: every backend (the in-house dem
// included) where the behaviour is common to all; the reference engines alone where it needs
// their rigid contact (dem's own tests cover those cases with its penalty contact)
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include <Eigen/Cholesky>

#include "engine_scenes.hpp"
#include "cases/case_analysis.hpp"
#include "registry.hpp"
#include "run/runner.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

constexpr double g = 9.81;

// build `scene` on `engine` and step it for `duration` seconds, calling `each` after every step
std::unique_ptr<Backend> run(const std::string& engine, const Scene& scene, const std::string& mode,
                             double duration, const std::function<void(const Sample&)>& each = {}) {
    auto backend = build_backend(engine, scene, mode);
    const long long steps = std::llround(duration / backend->time_step());
    for (long long i = 0; i < steps; ++i) {
        if (backend->step() != StepStatus::ok) FAIL(engine << " unstable: " << backend->failure());
        if (each) each(backend->sample());
    }
    return backend;
}

// the gap between the bottom of a unit-height block A and the top of its base at z = 0
double bottom_height(const Sample& s, double half_height) { return s.blocks[0].position.z() - half_height; }

}  // namespace

TEST_CASE("every backend: free fall follows g t^2 / 2", "[engines]") {
    const std::string engine = GENERATE(from_range(all_backend_names()));
    CAPTURE(engine);
    Scene s = base_scene("free_fall");
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 10), false);
    auto b = run(engine, s, "rigid", 1.0);
    Sample end = b->sample();
    const double t = end.t, dt = b->time_step();
    REQUIRE(t == Approx(1.0).epsilon(1e-9));
    // first-order (symplectic Euler) position error is g·t·dt/2: allow twice that
    CHECK(std::abs(end.blocks[0].position.z() - (10.0 - 0.5 * g * t * t)) <= g * t * dt);
    // velocities are integrated exactly for constant acceleration
    CHECK(end.blocks[0].velocity.z() == Approx(-g * t).epsilon(1e-9));
    // energy: kinetic + potential constant (the same first-order error bound, in J)
    double m = 2600.0;
    CHECK(std::abs(end.energy.kinetic + end.energy.potential - m * g * 10.0) <= m * g * g * t * dt);
}

TEST_CASE("every backend: matched contact rests at mg/(kn A)", "[engines]") {
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    CAPTURE(engine);
    Scene s = base_scene("rest");
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.3;   // settles within a few periods T = 0.058 s
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);
    auto b = run(engine, s, "matched", 1.0);
    Sample end = b->sample();
    const double expected = 2600.0 * g / (3e7 * 1.0);   // 8.502e-4 m
    const double penetration = -bottom_height(end, 0.5);
    CAPTURE(penetration, expected);
    WARN(engine << " matched rest: " << penetration << " m (" << (penetration - expected) / expected * 100 << " %)");
    // the criterion: within 2 % of the penalty spring's static deflection
    CHECK(penetration == Approx(expected).epsilon(0.02));
    CHECK(end.contacts > 0);
}

TEST_CASE("reference engines: rigid inelastic 10 cm drop does not rebound", "[engines]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    CAPTURE(engine);
    Scene s = base_scene("drop");
    s.contact.restitution = 0.0;
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.6), false);
    add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);
    const double t_hit = std::sqrt(2 * 0.1 / g);   // 0.1428 s
    double lowest = 1.0, highest_after = -1.0;
    run(engine, s, "rigid", 0.6, [&](const Sample& x) {
        double h = bottom_height(x, 0.5);
        if (x.t < t_hit + 0.01) return;
        lowest = std::min(lowest, h);
        highest_after = std::max(highest_after, h);
    });
    CAPTURE(lowest, highest_after);
    WARN(engine << " rigid drop: lowest " << lowest << " m, highest after impact " << highest_after << " m");
    // the criterion: rebound height under 1 mm
    CHECK(highest_after < 1e-3);
    // and the block did land (not sunk through or floating): within 1 cm of the base
    CHECK(std::abs(lowest) < 1e-2);
}

TEST_CASE("reference engines: H = 0.5 W slides at mu = 0.4 and holds at mu = 0.6", "[engines]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    const double mu = GENERATE(0.4, 0.6);
    // H at the centroid, or at the centre of the base (a moment about the centre of mass that the
    // base's friction balances: Bullet once crept there because its solver left the load's
    // torque impulse out of what friction acts on)
    const double point_z = GENERATE(0.0, -0.25);
    CAPTURE(engine, mu, point_z);
    Scene s = base_scene("friction");
    s.contact.friction = mu;
    add_box(s, "A", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.25), false);
    add_box(s, "B", Vec3(0.7, 4.0, 1.0), Vec3(0, 0, -0.5), true);
    const double weight = 325.0 * g;
    LoadDef h;
    h.block = 0;
    h.force = Vec3(0, 0.5 * weight, 0);
    h.point = Vec3(0, 0, point_z);   // no tipping either way: e = H h / W <= 0.125 m < B/2 (docs/physics.md case c)
    s.loads.push_back(h);
    // least-squares fit y = c0 + c1 t + c2 t² over 0.1 ... 0.5 s: a = 2 c2, insensitive to the
    // small rocking of a soft contact under the off-base push
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    double y_end = 0.0;
    run(engine, s, "rigid", 0.5, [&](const Sample& x) {
        y_end = x.blocks[0].position.y();
        if (x.t < 0.1 - 1e-9) return;
        Eigen::Vector3d basis(1.0, x.t, x.t * x.t);
        normal += basis * basis.transpose();
        rhs += basis * y_end;
    });
    if (mu == 0.4) {
        const double a = 2.0 * normal.ldlt().solve(rhs)[2];
        CAPTURE(a);
        WARN(engine << " sliding at H = 0.5 W, mu = 0.4: a = " << a << " m/s^2");
        // the criterion: a = (H/W - mu) g = 0.1 g within 2 %
        CHECK(a == Approx(0.1 * g).epsilon(0.02));
    } else {
        CAPTURE(y_end);
        WARN(engine << " holding at H = 0.5 W, mu = 0.6: slip " << y_end << " m in 0.5 s");
        // holding: H = 0.5 W < 0.6 W; a velocity-level solver may creep a little: 0.1 mm over 0.5 s
        CHECK(std::abs(y_end) < 1e-4);
    }
}

TEST_CASE("reference engines: slender rigid block first impact at Housner's t1", "[engines]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    // θ0 / α and the exact first-impact time from docs/physics.md (slender variant, 0.2 x 1.0)
    auto [ratio, t1] = GENERATE(table<double, double>({{0.5, 0.34709}, {0.8, 0.60376}}));
    CAPTURE(engine, ratio);
    const double alpha = std::atan(0.2 / 1.0);
    Scene s = rocking_block(ratio * alpha);
    double previous_angle = ratio * alpha, previous_t = 0.0, impact = -1.0;
    run(engine, s, "rigid", 0.7, [&](const Sample& x) {
        double angle = angle_about_y(x.blocks[0].orientation);
        if (impact < 0 && angle <= 0.0)
            impact = previous_t + (x.t - previous_t) * previous_angle / (previous_angle - angle);
        previous_angle = angle;
        previous_t = x.t;
    });
    CAPTURE(impact, t1, (impact - t1) / t1);
    WARN(engine << " rocking " << ratio << " alpha: t1 " << impact << " s (" << (impact - t1) / t1 * 100 << " %)");
    // the criterion: within 1 % of the exact rigid-body value
    CHECK(impact == Approx(t1).epsilon(0.01));
}

TEST_CASE("reference engines: a rocking block reports its contact on the pivot edge", "[engines]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    CAPTURE(engine);
    // released at 0.8 alpha about the edge x = 0.1 m, z = 0: it pivots there until the impact at 0.604 s
    Scene s = rocking_block(0.8 * std::atan(0.2 / 1.0));
    auto b = make_backend(engine);
    RunOptions options;
    options.record_contacts = true;
    b->build(s, options);
    const long long steps = std::llround(0.5 / b->time_step());
    long long reported = 0;
    for (long long i = 0; i < steps; ++i) {
        REQUIRE(b->step() == StepStatus::ok);
        const auto points = b->contact_points();
        if (!points.empty()) ++reported;
        double up = 0.0;
        for (const auto& c : points) {
            CHECK(c.position.x() == Approx(0.1).margin(1e-3));   // on the edge, within the solvers' slop
            CHECK(c.position.z() == Approx(0.0).margin(1e-3));
            up += std::abs(c.normal_force.z());
        }
        if (!points.empty()) CHECK(up > 0.0);
    }
    CAPTURE(reported, steps);
    // the pivot carries the block throughout: a solver that keeps its points a hair apart (Bullet's
    // split impulse) must still report them. MuJoCo's soft contact lets go for single steps as the
    // block speeds up (10 of 5000 measured), Siconos finds its first contacts after the first step.
    CHECK(reported >= steps * 99 / 100);
}

TEST_CASE("reference engines: general hexahedra rest like boxes", "[engines]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    CAPTURE(engine);
    // a box given as a hexahedron with its block frame at a corner rests on a hexahedral base
    Scene s = base_scene("hexahedra");
    add_hexahedron_box(s, "A", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.25), false);
    add_hexahedron_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);
    s.probes.push_back({"top", 0, Vec3(0.25, 0.25, 0.5)});
    auto b = run(engine, s, "rigid", 0.3);
    Sample end = b->sample();
    // the reported position is the centre of mass (0.25 m above the base), the probe the top centre;
    // a near-rigid contact leaves at most 1 mm of penetration
    CHECK(std::abs(end.blocks[0].position.z() - 0.25) < 1e-3);
    CHECK((end.blocks[0].position.head<2>()).norm() < 1e-6);
    CHECK(std::abs(end.probes[0].z() - 0.5) < 1e-3);
    CHECK(end.blocks[0].velocity.norm() < 1e-3);
}

TEST_CASE("every backend: the same scene twice gives identical samples", "[engines]") {
    const std::string engine = GENERATE(from_range(all_backend_names()));
    const std::string mode = GENERATE(as<std::string>{}, "rigid", "matched");
    CAPTURE(engine, mode);
    if (mode == "matched" && !has_matched_mode(engine)) return;   // rigid contact only
    Scene s = rocking_block(0.5 * std::atan(0.2));
    s.blocks[0].velocity = Vec3(0.05, 0.02, 0.0);
    std::vector<Sample> first, second;
    run(engine, s, mode, 0.4, [&](const Sample& x) { first.push_back(x); });
    run(engine, s, mode, 0.4, [&](const Sample& x) { second.push_back(x); });
    REQUIRE(first.size() == second.size());
    bool identical = true;
    for (size_t i = 0; i < first.size(); ++i) {
        const BlockState &a = first[i].blocks[0], &b = second[i].blocks[0];
        identical = identical && a.position == b.position && a.orientation.coeffs() == b.orientation.coeffs() &&
                    a.velocity == b.velocity && a.angular_velocity == b.angular_velocity &&
                    first[i].contacts == second[i].contacts;
    }
    CHECK(identical);
}

TEST_CASE("reference engines: the drum column overturns at a/g = B/H plus the ramp's lag", "[engines][structures]") {
    for (const std::string& engine : engine_names()) {
        CAPTURE(engine);
        // siconos: its NSGS takes ~116 iterations a step on this stack (12 coplanar contacts), so
        // the 34 s pushover costs ~100 s of wall time per simulated second: left out (docs/backends.md)
        if (engine == "siconos") continue;
        const Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/structures/column_pushover.toml", {});
        std::vector<Sample> samples;
        long long k = 0;
        const long long every = std::llround(s.run.output_interval / 1e-4);
        run(engine, s, "rigid", s.run.duration, [&](const Sample& x) {
            if (k++ % every == 0) samples.push_back(x);
        });
        const auto r = cases::analyse_case(s, samples, {false});
        REQUIRE(!r.metrics.empty());
        // measured 0.27056 (Bullet), 0.27065 (ODE), 0.26975 (MuJoCo) against the rigid monolith's
        // 0.27076: rigid contact is the limit analysis' own model, so 2 % holds with room
        INFO(r.metrics[0].name << ": " << r.metrics[0].value << " against " << r.metrics[0].reference);
        CHECK(r.metrics[0].pass());
    }
}

TEST_CASE("mujoco, rigid contact: a brick wall under El Centro keeps its bricks, no energy from nowhere", "[engines]") {
    const auto names = engine_names();
    if (std::find(names.begin(), names.end(), "mujoco") == names.end()) return;   // not built
    const Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/tests/backends/engines/wall_elcentro.toml", {});
    auto backend = make_backend("mujoco");
    RunOptions options;
    options.contact_mode = "rigid";
    const RunResult r = run_scene(*backend, s, options);
    REQUIRE(r.status == RunStatus::completed);
    INFO(energy_created_text(r));
    CHECK_FALSE(r.energy_created);
    double farthest = 0.0;
    for (const auto& x : r.samples)
        for (std::size_t b = 0; b < x.blocks.size(); ++b)
            farthest = std::max(farthest, (x.blocks[b].position - r.samples.front().blocks[b].position).norm());
    WARN("mujoco rigid wall under El Centro: farthest brick " << farthest << " m");
    // every engine moves a brick by less than 0.2 mm here (dem 0.15 mm, Bullet and ODE 0.02 mm,
    // measured); 1 mm passes them and fails a launched brick (MuJoCo's box-box collider: 6 m)
    CHECK(farthest < 1e-3);
}
