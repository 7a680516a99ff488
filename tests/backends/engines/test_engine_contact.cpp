// the matched penalty contact against the spring it stands for (frequency and static load of each
// interface in a stack) and the first sample of a step: one test body over every backend
#include <catch2/catch.hpp>

#include <cmath>

#include "engine_scenes.hpp"
#include "registry.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

constexpr double g = 9.81;
constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST_CASE("every backend: matched contact oscillates at sqrt(kn A / m)", "[engines][matched]") {
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    CAPTURE(engine);
    // scenarios/paper/stability.toml: a 1 m cube released just touching a fixed cube, undamped
    Scene s = base_scene("stability");
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);
    auto b = build_backend(engine, s, "matched");
    const double m = 2600.0, k = 3e7 * 1.0;
    const double period = 2.0 * kPi * std::sqrt(m / k);   // 0.058493 s
    const double rest = m * g / k;                        // 8.502e-4 m
    // upward crossings of the rest level by the penetration, linearly interpolated
    std::vector<double> crossings;
    double previous = 0.0, previous_t = 0.0, deepest = 0.0;
    const long long steps = std::llround(0.5 / b->time_step());
    for (long long i = 0; i < steps; ++i) {
        if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
        Sample x = b->sample();
        const double depth = 0.5 - x.blocks[0].position.z();
        deepest = std::max(deepest, depth);
        if (previous < rest && depth >= rest)
            crossings.push_back(previous_t + (x.t - previous_t) * (rest - previous) / (depth - previous));
        previous = depth;
        previous_t = x.t;
    }
    REQUIRE(crossings.size() >= 5);
    const double measured = (crossings.back() - crossings.front()) / (crossings.size() - 1);
    CAPTURE(measured, period, (measured - period) / period, deepest, 2 * rest);
    WARN(engine << " matched period " << measured << " s (" << (measured - period) / period * 100 << " %), deepest "
                << deepest << " m (" << (deepest - 2 * rest) / (2 * rest) * 100 << " %)");
    // the criterion: the period within 2 % of 2 pi sqrt(m / (kn A))
    CHECK(measured == Approx(period).epsilon(0.02));
    // released touching, an undamped spring swings to twice the static penetration (2 %)
    CHECK(deepest == Approx(2 * rest).epsilon(0.02));
}

TEST_CASE("every backend: each interface of a matched stack of three cubes carries its load",
          "[engines][matched]") {
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    CAPTURE(engine);
    Scene s = base_scene("stack");
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.5;   // settles in a few of the slowest periods (about 0.13 s)
    add_cube_stack(s, 3);
    auto b = build_backend(engine, s, "matched");
    const long long steps = std::llround(2.0 / b->time_step());
    for (long long i = 0; i < steps; ++i)
        if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
    Sample x = b->sample();
    const double unit = 2600.0 * g / 3e7;   // mg/(kn A) = 8.502e-4 m
    double below = 0.0;                      // top of the block below
    for (int i = 0; i < 3; ++i) {
        const double overlap = below - (x.blocks[i].position.z() - 0.5);
        const double expected = (3 - i) * unit;
        CAPTURE(i, overlap, expected, (overlap - expected) / expected);
        WARN(engine << " stack interface " << i << ": " << overlap << " m (" << (overlap - expected) / expected * 100
                    << " %)");
        // the criterion: each interface within 1 % of n mg/(kn A)
        CHECK(overlap == Approx(expected).epsilon(0.01));
        below = x.blocks[i].position.z() + 0.5;
    }
}

TEST_CASE("every backend: a matched cube thrown along its base stops at v^2/(2 mu g) without hopping",
          "[engines][matched]") {
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    CAPTURE(engine);
    // a 0.5 m cube thrown at 1 m/s on a flat base, mu = 0.5, kn = ks = 1e10 N/m³, undamped
    Scene s = base_scene("slide_stop");
    s.contact.kn = s.contact.ks = 1e10;
    s.contact.friction = 0.5;
    const int a = add_box(s, "A", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.25), false);
    add_box(s, "B", Vec3(3, 2, 0.5), Vec3(0.5, 0, -0.25), true);
    s.blocks[a].velocity = Vec3(1, 0, 0);
    s.run.settle = true;   // as a scene file gets by default: the springs start loaded by the weight
    auto b = build_backend(engine, s, "matched");
    const double stop = 1.0 / (2.0 * 0.5 * g);   // v²/(2 μ g) = 0.101937 m, reached at 0.204 s
    const Vec3 start = b->sample().blocks[0].position;
    double rise = 0.0;
    const long long steps = std::llround(0.5 / b->time_step());
    for (long long i = 0; i < steps; ++i) {
        if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
        rise = std::max(rise, b->sample().blocks[0].position.z() - start.z());
    }
    const double slide = b->sample().blocks[0].position.x() - start.x();
    CAPTURE(slide, stop, (slide - stop) / stop, rise);
    WARN(engine << " matched: slid " << slide << " m (" << (slide - stop) / stop * 100 << " %), rose " << rise << " m");
    // the shear springs' stretch μmg/(ks A) is 0.6 µm and the friction moment's tilt lifts the
    // centre by some µm (dem: 11 µm); 0.5 % and 0.1 mm leave room for a soft friction's stop
    const bool slid_right = std::abs(slide - stop) < 0.005 * stop;
    const bool stayed_down = rise < 1e-4;
    if (engine != "mujoco") {
        CHECK(slid_right);
        CHECK(stayed_down);
    } else {
        // a known miss, reported and not failed (docs/backends.md, "MuJoCo matched while sliding"):
        // in the elliptic cone's middle zone a sliding contact's normal force gains
        // friction·|J·a − a_ref| of its friction rows over R_normal, and the undamped springs let
        // that grow into hops (this cube: +7.7 %, 1.8 mm; +13 % at 2500 kg/m³; an impedance
        // d = 1e-4 instead of 1e-3 fixed the settled cube and broke it placed unsettled: chaotic)
        CHECK_NOFAIL(slid_right);
        CHECK_NOFAIL(stayed_down);
    }
}

TEST_CASE("every backend: the first sample after t = 0 holds the integrated pose", "[engines]") {
    const std::string engine = GENERATE(from_range(all_backend_names()));
    CAPTURE(engine);
    Scene s = base_scene("first_step");
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 10), false);
    s.blocks[0].angular_velocity = Vec3(0, 0, 1.0);   // rad/s
    auto b = build_backend(engine, s, "rigid");
    const double dt = b->time_step();
    Sample start = b->sample();
    REQUIRE(b->step() == StepStatus::ok);
    Sample first = b->sample();
    REQUIRE(first.t == Approx(dt).epsilon(1e-12));
    const double drop = start.blocks[0].position.z() - first.blocks[0].position.z();
    CAPTURE(drop, g * dt * dt);
    // one step of free fall moves the block by g dt^2 / 2 (exact) to g dt^2 (symplectic Euler);
    // a pose one step late would not have moved at all
    CHECK(drop >= 0.5 * g * dt * dt * (1 - 1e-6));
    CHECK(drop <= g * dt * dt * (1 + 1e-6));
    // and it turned by omega dt = 1e-4 rad about z (1e-6 rad: second-order terms)
    const double turned = first.blocks[0].orientation.angularDistance(start.blocks[0].orientation);
    CHECK(std::abs(turned - 1.0 * dt) < 1e-6);
}
