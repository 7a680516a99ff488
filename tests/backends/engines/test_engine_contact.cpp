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
