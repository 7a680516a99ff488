// the friction limit against Coulomb's mu W for a load at an angle to the block's edges (a pyramid
// or box friction model would hold up to sqrt(2) mu W at 45 degrees): the rigid reference engines
#include <catch2/catch.hpp>

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
