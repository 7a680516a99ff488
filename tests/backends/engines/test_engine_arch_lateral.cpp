// a semicircular arch under a constant horizontal acceleration against its limit-analysis
// collapse multiplier (compare/analytic/arch_lateral): the rigid reference engines
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "analytic/arch_lateral.hpp"
#include "engine_scenes.hpp"
#include "geometry/hexahedron.hpp"
#include "registry.hpp"
#include "scene/arch_builder.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

constexpr double g = 9.81;

// the crown's drop (m) after 1.5 s of a 21-voussoir arch (R = 1 m, t/R = 0.15, depth 0.5 m, μ = 1:
// no joint slides) under gravity and a horizontal ground acceleration of `ratio` times the
// collapse multiplier, ramped over 0.2 s and then held: a body force m·a on every voussoir, as a
// [ground_motion] gives it (applied at once, Bullet's rigid contact overshoots and lets the arch
// fall at 0.95 of it)
double crown_drop(const std::string& engine, double ratio) {
    const double lambda = oracle::ArchUnderLateralLoad{21, 0.15}.collapse_acceleration();
    Scene s = base_scene("arch_lateral");
    s.contact.friction = 1.0;
    add_arch(s, ArchSpec{21, 1.0, 0.15, 0.5, M_PI});
    int crown = -1, free = 0;   // the keystone V11 among the free blocks (a Sample's order)
    for (size_t i = 0; i < s.blocks.size(); ++i) {
        const BlockDef& b = s.blocks[i];
        if (b.name == "V11") crown = free;
        if (b.fixed) continue;
        ++free;
        LoadDef push;
        push.block = int(i);
        push.body = true;
        push.ramp = 0.2;
        const MassProperties mp = mass_properties(b.corners, 2600.0);
        push.force = Vec3(ratio * lambda * g * mp.mass, 0, 0);
        push.point = mp.centre;   // at the centre of mass, as the loader puts a ground motion's
        s.loads.push_back(push);
    }
    REQUIRE(crown >= 0);
    auto b = build_backend(engine, s, "rigid");
    const double z0 = b->sample().blocks[size_t(crown)].position.z();
    const long long steps = std::llround(1.5 / b->time_step());
    for (long long i = 0; i < steps; ++i)
        if (b->step() != StepStatus::ok) return z0 - b->sample().blocks[size_t(crown)].position.z();
    return z0 - b->sample().blocks[size_t(crown)].position.z();
}

}  // namespace

TEST_CASE("reference engines: an arch stands at 0.95 times its lateral collapse multiplier and falls at 1.05",
          "[engines][structures]") {
    // Siconos is left out for its time (about 100 s a run here); run by hand it held to 3e-6 m
    // at 0.95 and let the crown fall 0.96 m at 1.05 (docs/validation.md)
    std::vector<std::string> engines;
    for (const auto& e : engine_names())
        if (e != "siconos") engines.push_back(e);
    const std::string engine = GENERATE_COPY(from_range(engines));
    CAPTURE(engine);
    const double held = crown_drop(engine, 0.95), fell = crown_drop(engine, 1.05);
    WARN(engine << ": crown drop " << held << " m at 0.95 λ, " << fell << " m at 1.05 λ");
    // standing: the contacts' own give (Bullet's rigid contact measured 1.5 mm in 2 s under a
    // ramped load): under 1 cm; falling: the four-hinge mechanism drops the crown by metres
    // within 1.5 s (measured 0.95 to 1.9 m at 2 s): more than 0.1 m
    CHECK(held < 0.01);
    CHECK(fell > 0.1);
}
