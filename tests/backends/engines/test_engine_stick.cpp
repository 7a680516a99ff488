// a block pushed at its top below the Coulomb limit on every backend, with most of its base lifted:
// it must hold, judged by the stick reference kind (its ringing on the springs is no slip)
#include <catch2/catch.hpp>

#include <cmath>

#include "cases/case_analysis.hpp"
#include "engine_scenes.hpp"

using namespace cairn;
using namespace cairn::test;

TEST_CASE("every backend: a cube pushed at its top by 0.45 W holds on the 15 % of its base still pressed",
          "[engines][stick]") {
    const std::string engine = GENERATE(from_range(all_backend_names()));
    CAPTURE(engine);
    // a 0.5 m cube (325 kg) on a fixed slab, μ = 0.6, pushed at the middle of its top edge by
    // H = 0.45 W, ramped over 0.5 s, for 2 s. H·h/W = 0.225 m of the 0.25 m half-base: on springs of
    // kn = 1e9 N/m³ only c = 3(B/2 − e) = 0.073 m of the base presses (a 2.3 mrad tilt). On dem the
    // block then rocks on that strip with a 0.36 s period, lightly damped (its contact damping is a
    // ratio of the whole face's vertical mode: ζ·ω_rock/ω_face ≈ 0.002), by ±8 µm for as long as the
    // load stays; a straight line through that swing read −7.3 µm of drift over the second half
    // (a miss at 5 % of the 50 µm base shear), the lines through its turning points read 2.6e-8 m
    Scene s = base_scene("stick_top");
    s.run.duration = 2.0;
    s.contact.kn = s.contact.ks = 1e9;
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.05;
    const int a = add_box(s, "A", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.25), false);
    add_box(s, "B", Vec3(3.0, 3.0, 0.5), Vec3(0, 0, -0.25), true);
    const double H = 0.45 * 325.0 * 9.81;
    LoadDef push;
    push.block = a;
    push.force = Vec3(H, 0, 0);
    push.point = Vec3(0, 0, 0.25);
    push.ramp = 0.5;
    s.loads.push_back(push);
    s.reference = ReferenceDef{"stick", a, {{"force", H}}};
    const bool dem = engine == "dem";
    const auto r = cases::analyse_case(s, sampled_run(engine, s), {dem, dem});
    const auto& held = find_metric(r, "slip while held");
    CAPTURE(held.value, held.basis);
    if (engine == "mujoco") {
        // MuJoCo's soft friction creeps at a steady 10 µm/s (measured 15.4 µm over the second
        // half): a known miss, pinned so that a change shows (docs/backends.md)
        CHECK(std::string(held.verdict()) == "miss");
        CHECK(held.value > 0.0);
        CHECK(held.value < 3e-5);
    } else {
        CHECK(std::string(held.verdict()) == "pass");
    }
    if (dem) {
        // the ramp is 1.4 periods of the rocking: the quasi-static base shear is shown, not judged
        CHECK(std::string(find_metric(r, "base shear displacement").verdict()) == "info");
        CHECK_THAT(find_metric(r, "base shear displacement").basis, Catch::Contains("not slow"));
    }
}
