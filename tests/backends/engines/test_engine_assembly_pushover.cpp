// a pushover that is not a centred stack pushed along a side, on every backend, judged by the
// pushover reference kind against the rigid-block limit analysis of the scene's blocks
// (compare/cases/assembly_pushover.hpp)
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "cases/case_analysis.hpp"
#include "engine_scenes.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;
using namespace cairn::test;

TEST_CASE("every backend: a column pushed at 30 degrees to its faces tips over its base edge at the limit analysis's "
          "multiplier",
          "[engines][pushover]") {
    const std::string engine = GENERATE(from_range(all_backend_names()));
    CAPTURE(engine);
    // the shipped column_pushover (three drums 0.4 × 0.4 × 0.5 m, μ = 0.8) shaken 30° off its x
    // faces by a ramp of 0.28 g at 2 s, then 2.5e-3 g/s: the resultant leaves the base through
    // its side x = B/2 at λ = (B/2)/(H/2·cos 30°) = 0.3079. Measured (a/g at 0.05 rad): ODE
    // 0.3112, MuJoCo 0.3117, Bullet 0.3119, Siconos 0.3120, against the mechanism's lagged bound
    // 0.3141 and 0.98 of λ with its joints hinging 1 mm inside (0.3003); dem 0.2967 (kn 1e9: its
    // penalty joints hinge further inside, so it is judged from above only)
    const std::vector<Override> set{parse_override("ground_motion.direction=[0.8660254037844387, 0.5, 0.0]"),
                                    parse_override("ground_motion.time=[0.0, 2.0, 42.0]"),
                                    parse_override("ground_motion.acceleration=[0.0, 0.28, 0.38]"),
                                    parse_override("run.duration=16")};
    const Scene scene = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/structures/column_pushover.toml", set);
    const bool dem = engine == "dem";
    const auto a = cases::analyse_case(scene, sampled_run(engine, scene, "rigid", 1e-2), {dem, dem});
    CHECK(check_judged(a) == (dem ? 1 : 2));
}

namespace {

// the shipped column_pushover with drums 0.6, 0.5 and 0.4 m wide (μ = 0.8) on dem's overlap
// contact, under a ramp of 0.45 g at 2 s, then 0.01 g/s: the base joint governs,
// λ = b·Σm/Σ(m·z) = 0.3·0.77/0.4775 = 0.4838 (by hand; the upper joints 0.5616 and 0.8)
Scene tapered_column(const std::string& ode_stepper) {
    const std::vector<Override> set{parse_override("contact.scheme=\"overlap\""),
                                    parse_override("blocks.D1.size=[0.6, 0.6, 0.5]"),
                                    parse_override("blocks.D2.size=[0.5, 0.5, 0.5]"),
                                    parse_override("ground_motion.time=[0.0, 2.0, 42.0]"),
                                    parse_override("ground_motion.acceleration=[0.0, 0.45, 0.85]"),
                                    parse_override("run.duration=9"),
                                    parse_override("backends.ode.stepper=\"" + ode_stepper + "\"")};
    return load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/structures/column_pushover.toml", set);
}

}  // namespace

TEST_CASE("every backend: a tapered column tips about its base at its multiplier plus the ramp's lag", "[engines][pushover]") {
    const std::string engine = GENERATE(from_range(all_backend_names()));
    CAPTURE(engine);
    // ODE on QuickStep, as docs/backends.md advises for a stack of unequal blocks (its dWorldStep
    // slides this column, below); judged within 2 % of the monolith's (dem: the Winkler stack's).
    // Measured at 0.01 g/s from 0.2 g: dem −0.53 %, Bullet −0.18 %, ODE −0.23 %, MuJoCo −0.36 %,
    // Siconos −0.17 %
    const Scene scene = tapered_column("quickstep");
    const bool dem = engine == "dem";
    const auto a = cases::analyse_case(scene, sampled_run(engine, scene, "rigid", 1e-2), {dem, dem});
    CHECK(check_judged(a) == 1);
}

TEST_CASE("ODE's dWorldStep slides a tapered column along its base at its tipping point", "[engines][pushover]") {
    // pins the documented miss (docs/backends.md): at a/g = 0.484 the direct solver lets the whole
    // column slide without turning (μ = 0.8), so it turns 0.05 rad late (measured at 0.01 g/s from
    // 0.2 g: 0.5133 against 0.4963, +3.4 %); when an ODE update fixes it, this fails and the docs
    // and the shipped column's advice need the news
    const auto names = engine_names();
    if (std::find(names.begin(), names.end(), "ode") == names.end()) return;   // not built in
    const Scene scene = tapered_column("step");
    const auto a = cases::analyse_case(scene, sampled_run("ode", scene, "rigid", 1e-2), {false, false});
    const auto& m = find_metric(a, "a/g when the top turns 0.0500 rad");
    INFO(m.value << " against " << m.reference);
    CHECK_FALSE(m.pass());
    CHECK(m.value > m.reference);
}
