// the friction limit against Coulomb's mu W for a load at an angle to the block's edges (a pyramid
// or box friction model would hold up to sqrt(2) mu W at 45 degrees): the rigid reference engines
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "engine_scenes.hpp"
#include "registry.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

constexpr double g = 9.81;
constexpr double kPi = 3.14159265358979323846;

// does a 0.5 m cube (mu = 0.6) on a fixed base slide under a constant horizontal force of
// `ratio` mu W at `angle` (rad) to its x edges, applied at its centre? (moves > 1 mm in 0.4 s)
bool slides(const std::string& engine, double angle, double ratio) {
    Scene s = base_scene("friction_angle");
    add_box(s, "A", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.25), false);
    add_box(s, "B", Vec3(4.0, 4.0, 1.0), Vec3(0, 0, -0.5), true);
    const double weight = 325.0 * g;
    LoadDef h;
    h.block = 0;
    h.force = ratio * s.contact.friction * weight * Vec3(std::cos(angle), std::sin(angle), 0);
    h.point = Vec3::Zero();   // the centre: no tipping below H = W (mu W = 0.6 W)
    s.loads.push_back(h);
    auto b = make_backend(engine);
    b->build(s, RunOptions{});
    const long long steps = std::llround(0.4 / b->time_step());
    for (long long i = 0; i < steps; ++i)
        if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
    return b->sample().blocks[0].position.head<2>().norm() > 1e-3;
}

}  // namespace

TEST_CASE("reference engines: a load at 0, 30 and 45 degrees to the edges slides at mu W", "[engines][friction]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    const double degrees = GENERATE(0.0, 30.0, 45.0);
    CAPTURE(engine, degrees);
    const double angle = degrees * kPi / 180.0;
    // bisection on the force between 0.9 mu W and 1.6 mu W (a box limit reaches 1.41 mu W)
    double lo = 0.9, hi = 1.6;
    REQUIRE_FALSE(slides(engine, angle, lo));
    REQUIRE(slides(engine, angle, hi));
    while (hi - lo > 2e-3) {
        const double mid = 0.5 * (lo + hi);
        (slides(engine, angle, mid) ? hi : lo) = mid;
    }
    const double threshold = 0.5 * (lo + hi);
    WARN(engine << " at " << degrees << " deg: slides at " << threshold << " mu W");
    // the criterion: within 2 % of mu W. The detection itself reads high by the force
    // that moves the block 1 mm in 0.4 s, 0.2 % of mu W, and the bisection stops at 0.2 %
    CHECK(threshold == Approx(1.0).epsilon(0.02));
}

namespace {

// the mean distance from the centre of a square of side a to its points, over a: the torque that
// uniform pressure p and friction mu resist a twist about the centre with is mu·p·a²·(this)·a
const double kSquareMeanRadius = (std::sqrt(2.0) + std::log(1.0 + std::sqrt(2.0))) / 6.0;   // 0.382598

// the uniform-pressure twist limit mu·W·a·0.3826 of the 0.4 m cube of twist_scene, N·m
double twist_limit() { return 0.5 * 2600.0 * 0.064 * g * 0.4 * kSquareMeanRadius; }

// a 0.4 m cube (mu = 0.5, kn = ks = 1e10 N/m³) on a fixed base under a couple about z of `ratio`
// times twist_limit(), ramped over `ramp` (s): two opposite forces along x at mid-height, 0.2 m
// either side of the centre
Scene twist_scene(double ratio, int subdivision, double ramp) {
    Scene s = base_scene("friction_twist");
    s.contact.kn = s.contact.ks = 1e10;
    s.contact.friction = 0.5;
    s.contact.subdivision = subdivision;
    s.run.settle = true;   // as a scene file gets by default: dem starts with its springs loaded
    add_box(s, "A", Vec3(0.4, 0.4, 0.4), Vec3(0, 0, 0.2), false);
    add_box(s, "B", Vec3(2.0, 2.0, 0.4), Vec3(0, 0, -0.2), true);
    const double torque = ratio * twist_limit();   // N·m
    for (double side : {-1.0, 1.0}) {
        LoadDef h;
        h.block = 0;
        h.force = Vec3(-side * torque / 0.4, 0, 0);   // the pair's moment about z: +torque
        h.point = Vec3(0, 0.2 * side, 0);
        h.ramp = ramp;
        s.loads.push_back(h);
    }
    return s;
}

// does the cube of twist_scene, the couple applied at once, turn by more than 1e-3 rad in 0.4 s?
bool twists(const std::string& engine, double ratio, int subdivision) {
    auto b = make_backend(engine);
    b->build(twist_scene(ratio, subdivision, 0.0), RunOptions{});
    const long long steps = std::llround(0.4 / b->time_step());
    for (long long i = 0; i < steps; ++i)
        if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
    return b->sample().blocks[0].orientation.angularDistance(Quat::Identity()) > 1e-3;
}

// the couple (in units of the uniform-pressure limit) at which the cube starts to turn, by
// bisection between lo and hi to 0.2 %
double twist_threshold(const std::string& engine, double lo, double hi, int subdivision = 4) {
    REQUIRE_FALSE(twists(engine, lo, subdivision));
    REQUIRE(twists(engine, hi, subdivision));
    while (hi - lo > 2e-3) {
        const double mid = 0.5 * (lo + hi);
        (twists(engine, mid, subdivision) ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("dem: a cube twisted about its base's normal turns at the torque its face's friction resists",
          "[engines][friction]") {
    // Coulomb friction under uniform pressure resists a twist about the face's centre with
    // mu·W·a·0.3826 (the mean distance from a square's centre). dem's overlap contact puts the
    // friction of each of its n × n sub-contacts at the sub-cell's centre, and each sub-contact's
    // torsion spring, a disc of its area, adds its own twist on an elliptic interaction with its
    // shear (docs/dem.md, "Twisting a face"). All sliding, the shear springs alone hold the
    // midpoint rule of that mean (0.9786 of it at n = 4, 0.9943 at n = 8); at the most, each
    // sub-contact holds μ·F_n·√(r² + r_d²) (r its distance from the centre, r_d = (2/3)√(A/π)
    // the disc's mean radius): 1.0138 at n = 4, 1.0038 at n = 8. At n = 1, r = 0: the disc alone
    const int n = GENERATE(1, 4, 8);
    CAPTURE(n);
    const double disc = (2.0 / 3.0) / std::sqrt(3.14159265358979323846 * n * n);
    double midpoint = 0.0, most = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double r = std::hypot((i + 0.5) / n - 0.5, (j + 0.5) / n - 0.5);
            midpoint += r;
            most += std::hypot(r, disc);
        }
    midpoint /= n * n * kSquareMeanRadius;
    most /= n * n * kSquareMeanRadius;
    if (n == 1) midpoint = most;
    const double threshold = twist_threshold("dem", 0.9, 1.2, n);
    WARN("dem at subdivision " << n << ": turns at " << threshold << " of mu W a 0.3826 (midpoint rule " << midpoint
                               << ", most " << most << ")");
    // between the two within the bisection's 0.2 % and the detection's bias (the excess couple
    // that turns the cube 1e-3 rad in 0.4 s, 0.05 %): 0.5 % (measured 0.9932 at n = 4)
    CHECK(threshold > midpoint * (1.0 - 0.005));
    CHECK(threshold < most * (1.0 + 0.005));
    // and the uniform-pressure limit within the midpoint rule's error at n = 8, 1 %
    if (n == 8) CHECK(threshold == Approx(1.0).epsilon(0.01));
}

TEST_CASE("reference engines: a twisted cube holds until the friction at its face's four corners gives out",
          "[engines][friction]") {
    // a pinned behaviour, the capability matrix's "friction against twisting" row: each engine
    // carries a face's contact at the four corners of its manifold, whose friction resists a
    // twist with mu·W·a/√2 when they share the weight equally: 1.848 times the uniform-pressure
    // limit mu·W·a·0.3826 that dem reaches (docs/backends.md, "Twisting a face")
    const std::string engine = GENERATE(from_range(engine_names()));
    CAPTURE(engine);
    const double threshold = twist_threshold(engine, 0.9, 2.2);
    WARN(engine << ": turns at " << threshold << " of mu W a 0.3826");
    // corners sharing the weight equally, within the bisection's 0.2 % and 1 % for a solver's
    // uneven split of the weight among the four points
    CHECK(threshold == Approx(1.0 / (std::sqrt(2.0) * kSquareMeanRadius)).epsilon(0.012));
}

namespace {

/// a scene for blocks sliding on stone: mu = 0.5, kn = ks = 1e10 N/m³, started settled, with
/// contact damping ζ = 0.05 for dem (undamped, its elastic-Coulomb joints flutter while they
/// slide: the blocks hop by up to 1 cm, docs/dem.md, "Flutter of undamped sliding contact")
Scene sliding_scene(const std::string& name) {
    Scene s = base_scene(name);
    s.contact.kn = s.contact.ks = 1e10;
    s.contact.friction = 0.5;
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.05;
    s.run.settle = true;
    return s;
}

}  // namespace

TEST_CASE("every backend: three cubes pushed along a row slide together at (F - 3 mu W) / 3m and stay down",
          "[engines][friction]") {
    const std::string engine = GENERATE(from_range(all_backend_names()));
    CAPTURE(engine);
    // three 0.4 m cubes side by side on a fixed base (mu = 0.5, kn = ks = 1e10 N/m³), the first
    // pushed along the row by 1.5 times the row's friction, 0.1 m above the base
    Scene s = sliding_scene("friction_row");
    for (int i = 0; i < 3; ++i) add_box(s, std::string(1, char('A' + i)), Vec3(0.4, 0.4, 0.4), Vec3(0.4 * i, 0, 0.2), false);
    add_box(s, "G", Vec3(4.0, 2.0, 0.4), Vec3(0.8, 0, -0.2), true);
    const double m = 2600.0 * 0.064, weight = m * g;
    LoadDef push;
    push.block = 0;
    push.force = Vec3(1.5 * 0.5 * 3 * weight, 0, 0);
    push.point = Vec3(0, 0, -0.1);
    s.loads.push_back(push);
    auto b = build_backend(engine, s, "rigid");
    const double t = 0.5;
    const long long steps = std::llround(t / b->time_step());
    double rise = 0.0, turn = 0.0;
    for (long long i = 0; i < steps; ++i) {
        if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
        for (int k = 0; k < 3; ++k) {
            const auto& blk = b->sample().blocks[size_t(k)];
            rise = std::max(rise, blk.position.z() - 0.2);
            turn = std::max(turn, blk.orientation.angularDistance(Quat::Identity()));
        }
    }
    const double expected = 0.5 * (0.5 * 0.5 * g) * t * t;   // (F − 3μW)/(3m) = 0.5 μ g: 0.30656 m
    const double slid = b->sample().blocks[0].position.x();
    WARN(engine << ": slid " << slid << " m (" << (slid - expected) / expected * 100 << " %), rose " << rise
                << " m, turned " << turn << " rad");
    // 1 %: the criterion for a slide; dem's shear springs stretch μ m g/(ks A) = 5 µm
    const bool slid_right = std::abs(slid - expected) < 0.01 * expected;
    // the push's moment, F·0.1 m = 0.225 W·m, is far below the row's 3W·0.6 m about its front
    // edge: no block lifts. 0.1 mm and 1e-3 rad leave room for the springs' tilt under the push
    const bool stayed = rise < 1e-4 && turn < 1e-3;
    if (engine == "mujoco") {
        // known misses, reported and not failed (docs/backends.md, "A row of blocks pushed along"):
        // MuJoCo slides 4 % too far, and its blocks rise and turn
        CHECK_NOFAIL(slid_right);
        CHECK_NOFAIL(stayed);
    } else if (engine == "ode") {
        // ODE slides right, but its row turns and drifts sideways by an amount that jumps with the
        // push's last digits (5 to 13 mm at 3672.85 to 3673.5 N; here 4e-4 rad): a reported miss
        CHECK(slid_right);
        CHECK_NOFAIL(stayed);
    } else {
        CHECK(slid_right);
        CHECK(stayed);
    }
}

TEST_CASE("every backend: a block riding on a pushed block moves with it at (F - 2 mu W) / 2m below mu g",
          "[engines][friction]") {
    const std::string engine = GENERATE(from_range(all_backend_names()));
    CAPTURE(engine);
    // two 0.5 m cubes stacked on a fixed base (mu = 0.5, kn = ks = 1e10 N/m³, ζ 0.05), the lower
    // one pushed at its centre by 3 mu W: the pair slides at a = (F - 2 mu W)/(2m) = 0.5 mu g, and
    // the upper one needs m a = 0.5 mu W of friction to ride along, half its limit
    Scene s = sliding_scene("friction_rider");
    add_box(s, "L", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.25), false);
    add_box(s, "U", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.75), false);
    add_box(s, "G", Vec3(6.0, 2.0, 0.4), Vec3(2.0, 0, -0.2), true);
    const double weight = 2600.0 * 0.125 * g;
    LoadDef push;
    push.block = 0;
    push.force = Vec3(3.0 * 0.5 * weight, 0, 0);
    push.point = Vec3::Zero();
    s.loads.push_back(push);
    auto b = build_backend(engine, s, "rigid");
    const double t = 1.0;
    const long long steps = std::llround(t / b->time_step());
    double rise = 0.0, offset_half = 0.0;   // the rider's offset at t/2, m
    auto offset = [&] { return b->sample().blocks[1].position.x() - b->sample().blocks[0].position.x(); };
    for (long long i = 1; i <= steps; ++i) {
        if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
        rise = std::max(rise, b->sample().blocks[0].position.z() - 0.25);
        if (i == steps / 2) offset_half = offset();
    }
    const double expected = 0.5 * (0.5 * 0.5 * g) * t * t;   // 1.22625 m
    const double lower = b->sample().blocks[0].position.x();
    WARN(engine << ": lower slid " << lower << " m (" << (lower - expected) / expected * 100 << " %), the rider "
                << offset() << " m off it (" << offset() - offset_half << " m in the last half), the lower block rose "
                << rise << " m");
    // 1 %: the criterion for a slide (dem's shear springs stretch 2 μ m g/(ks A) = 1.3 µm)
    const bool slid_right = std::abs(lower - expected) < 0.01 * expected;
    // the rider holds. Rigid contact: within 0.1 mm of the lower block (measured 0.1 to 2 µm).
    // dem: within 1 mm. The push beats the base's friction at once, so the rider's shear springs
    // take half its friction limit suddenly, overshoot towards twice that while the pair's tilt
    // rings, and slip once, 0.12 mm here (0.17 mm at dt = "auto"; docs/dem.md, "Holding under
    // loads"; its elastic shear is 0.3 µm). Every backend: no creep, under 10 µm in the last half
    const double allowed = engine == "dem" ? 1e-3 : 1e-4;
    const bool rode = std::abs(offset()) < allowed && std::abs(offset() - offset_half) < 1e-5;
    if (engine == "mujoco") {
        // a known miss, reported and not failed (docs/backends.md, "A block riding on a pushed
        // block"): MuJoCo's convex contact lifts a sliding block, the pair hops off the base, the
        // push then beats the rider's friction, and the pair slides 8 % too far
        CHECK_NOFAIL(slid_right);
        CHECK_NOFAIL(rode);
    } else {
        CHECK(slid_right);
        CHECK(rode);
    }
}

TEST_CASE("dem: a couple below the twist limit, ramped and held undamped, twists the cube elastically and no more",
          "[engines][friction]") {
    // a couple ramped over 1 s and held 3 s more, no contact damping (issue 11, "holding holds",
    // for a twist); returns the twist (rad) when fully applied, 1 s later and at the end
    auto twist = [](double ratio) {
        auto b = make_backend("dem");
        b->build(twist_scene(ratio, 4, 1.0), RunOptions{});
        auto yaw = [&] { return b->sample().blocks[0].orientation.angularDistance(Quat::Identity()); };
        double at_full = 0.0, later = 0.0;
        const long long steps = std::llround(4.0 / b->time_step());
        for (long long i = 1; i <= steps; ++i) {
            if (b->step() != StepStatus::ok) FAIL("dem unstable: " << b->failure());
            if (i == std::llround(1.0 / b->time_step())) at_full = yaw();
            if (i == std::llround(2.0 / b->time_step())) later = yaw();
        }
        return std::array<double, 3>{at_full, later, yaw()};
    };
    // 0.7 of mu·W·a·0.3826: every sub-contact sticks (the corner ones, loaded most, slip from
    // 0.77), so the twist is T/(ks·J) with the sub-contacts' polar moment: the midpoint rule of
    // a⁴/6, (1 − 1/n²)·a⁴/6 at n = 4, plus their own torsion springs, n² discs of (a/n)⁴/2π;
    // 1 % for the ringing the ramp leaves in the springs
    const double polar = (1.0 - 1.0 / 16.0) * std::pow(0.4, 4) / 6.0 + std::pow(0.4, 4) / (16.0 * 2.0 * 3.14159265358979323846);
    const double elastic = 0.7 * twist_limit() / (1e10 * polar);
    const auto [stuck, stuck_later, stuck_end] = twist(0.7);
    CAPTURE(stuck, stuck_later, stuck_end, elastic);
    CHECK(stuck == Approx(elastic).epsilon(0.01));
    // 0.95 of dem's own limit (0.9786 at n = 4): the outer sub-contacts slip and the cube turns
    // further while the couple grows (1 % more in the second after the ramp, as the slip settles),
    // then holds: over the last 2 s it turns by less than 1 % of its twist. The undamped springs
    // ring by 0.2 % of it after the slip (−0.19 % here; at the auto time step 0 to 5 digits over
    // 6 s); a walk would keep turning one way
    // (the torsion springs of the sub-contacts hold part of it: it turns 11 % past the elastic
    // twist of that couple, 0.95·0.9786/0.7 times the one above; 5 % shows that the slip happened)
    const auto [reached, later, end] = twist(0.95 * 0.9786);
    CAPTURE(reached, later, end);
    CHECK(reached > 1.05 * (0.95 * 0.9786 / 0.7) * elastic);
    CHECK(std::abs(end - later) < 0.01 * later);
}
