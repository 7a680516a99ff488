// a block pushed at its top below the Coulomb limit on every backend, with most of its base lifted:
// it must hold, judged by the stick reference kind (its ringing on the springs is no slip)
#include <catch2/catch.hpp>

#include <cmath>

#include "cases/case_analysis.hpp"
#include "engine_scenes.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

// 2 s of a scene on contact springs kn = ks (N/m³) damped at ζ = 0.05
void stick_contact(Scene& s, double kn) {
    s.run.duration = 2.0;
    s.contact.kn = s.contact.ks = kn;
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.05;
}

// block pushed along x by H (N) at `point` (block frame, m), ramped over 0.5 s, judged by the
// stick reference
void push_held(Scene& s, int block, double H, const Vec3& point) {
    LoadDef push;
    push.block = block;
    push.force = Vec3(H, 0, 0);
    push.point = point;
    push.ramp = 0.5;
    s.loads.push_back(push);
    s.reference = ReferenceDef{"stick", block, {{"force", H}}};
}

}  // namespace

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
    stick_contact(s, 1e9);
    const int a = add_box(s, "A", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.25), false);
    add_box(s, "B", Vec3(3.0, 3.0, 0.5), Vec3(0, 0, -0.25), true);
    push_held(s, a, 0.45 * 325.0 * 9.81, Vec3(0, 0, 0.25));
    const bool dem = engine == "dem";
    const auto r = cases::analyse_case(s, sampled_run(engine, s), {dem, dem});
    const auto& held = find_metric(r, "slip while held");
    CAPTURE(held.value, held.basis);
    // every engine holds; MuJoCo's soft friction crept 15.4 µm over the second half (a miss) at
    // impratio 1, 0.15 µm at its default 100 (docs/backends.md)
    CHECK(std::string(held.verdict()) == "pass");
    if (dem) {
        // the ramp is 1.4 periods of the rocking: the quasi-static base shear is shown, not judged
        CHECK(std::string(find_metric(r, "base shear displacement").verdict()) == "info");
        CHECK_THAT(find_metric(r, "base shear displacement").basis, Catch::Contains("not slow"));
    }
}

namespace {

// two 0.5 m cubes (325 kg each) stacked on a fixed slab, μ = 0.6, kn = ks = 1e10 N/m³, ζ = 0.05;
// the top one pushed at its centre by half its weight (0.83 of its friction limit), ramped over
// 0.5 s, for 2 s: the stick reference on the top cube
Scene pushed_stack() {
    Scene s = base_scene("stack_hold");
    stick_contact(s, 1e10);
    add_box(s, "low", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.25), false);
    const int top = add_box(s, "top", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.75), false);
    add_box(s, "base", Vec3(2.0, 2.0, 0.4), Vec3(0, 0, -0.2), true);
    push_held(s, top, 0.5 * 325.0 * 9.81, Vec3::Zero());
    return s;
}

}  // namespace

TEST_CASE("every backend: the top cube of a stack pushed by half its weight holds on the cube below", "[engines][stick]") {
    const std::string engine = GENERATE(from_range(all_backend_names()));
    CAPTURE(engine);
    // judged at 5 % of the quasi-static base shear (60 nm of drift over the second second).
    // Measured: dem 18 nm over the lines through its rocking's turning points, Siconos 1e-19 m;
    // ODE 0.22 µm with its ringing too slow to judge (39 µm at 50 iterations, its default until
    // session 21); Bullet 0.74 µm (53 nm at 100 iterations, 2e-12 m at 200); MuJoCo 0.39 µm (39 µm
    // at impratio 1)
    const Scene s = pushed_stack();
    const bool dem = engine == "dem";
    const auto r = cases::analyse_case(s, sampled_run(engine, s), {dem, dem});
    const auto& held = find_metric(r, "slip while held");
    CAPTURE(held.value, held.basis);
    const std::string verdict = held.verdict();
    if (engine == "mujoco") {
        // its soft friction's creep (docs/backends.md), a hundredth of what it was at impratio 1,
        // pinned so that a change shows
        CHECK(verdict == "miss");
        CHECK(held.value < 1e-6);
    } else if (engine == "bullet") {
        // 50 iterations of its sequential impulses leave a creep of under a micrometre a second:
        // pinned, and gone at 200 (docs/backends.md)
        CHECK(verdict == "miss");
        CHECK(std::abs(held.value) < 2e-6);
        Scene more = s;
        more.backend_settings["bullet"]["iterations"] = {200LL, "test"};
        const auto r200 = cases::analyse_case(more, sampled_run(engine, more), {false, false});
        CHECK(std::string(find_metric(r200, "slip while held").verdict()) == "pass");
    } else if (engine == "ode") {
        // its ringing is too slow for the window: the slip is shown, not judged; bounded here
        CHECK(std::abs(held.value) < 1e-6);
    } else {
        CHECK(verdict == "pass");
    }
}
