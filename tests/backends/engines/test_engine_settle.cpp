// The settled start on the engines' matched (penalty) contact: MuJoCo matched settles its blocks on
// their springs before t = 0 as dem does (docs/dem.md, "Settled start")
#include <catch2/catch.hpp>

#include <cmath>

#include "engine_scenes.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

// how far a 0.4 m cube released just touching a 20° plane (μ = 0.6, kn = ks = 1e9 N/m³, no contact
// damping) slides down it in `duration` s on MuJoCo matched, settled or started as placed, m
double incline_slide(bool settle, double duration) {
    const double theta = 20.0 * M_PI / 180.0;
    Scene s = base_scene("incline");
    s.contact.kn = s.contact.ks = 1e9;
    s.run.settle = settle;
    s.run.duration = duration;
    const Quat q(Eigen::AngleAxisd(theta, Vec3::UnitY()));
    add_box(s, "B", Vec3(3.0, 2.0, 0.5), q * Vec3(0, 0, -0.25), true);
    s.blocks.back().orientation = q;
    add_box(s, "A", Vec3(0.4, 0.4, 0.4), q * Vec3(0, 0, 0.2), false);
    s.blocks.back().orientation = q;
    auto b = build_backend("mujoco", s, "matched");
    const Vec3 down = q * Vec3::UnitX(), start = b->sample().blocks[0].position;
    const long steps = long(std::ceil(duration / b->time_step() - 1e-9));
    bool stable = true;
    for (long i = 0; i < steps && stable; ++i) stable = b->step() == StepStatus::ok;
    REQUIRE(stable);
    return (b->sample().blocks[0].position - start).dot(down);
}

}  // namespace

TEST_CASE("MuJoCo matched: a block settled on an incline flatter than atan(mu) holds", "[engines][matched][settle]") {
    if (!has_matched_mode("mujoco")) return;
    // as placed, the undamped springs bounce from the release and the friction cap vanishes at
    // each top: it slides (measured 5.2 mm in 0.2 s, 92 mm in 2 s)
    CHECK(incline_slide(false, 0.5) > 5e-3);
    // settled, what is left is MuJoCo's soft friction, which creeps as in its rigid mode: 4.2 µm
    // in 0.5 s at impratio 1, 0.042 µm at the backend's 100 (docs/backends.md, "MuJoCo's creep");
    // bounded at 1 µm over 0.5 s, a 5000th of the slide
    const double settled = incline_slide(true, 0.5);
    INFO("settled: " << settled << " m");
    CHECK(std::abs(settled) < 1e-6);
}
