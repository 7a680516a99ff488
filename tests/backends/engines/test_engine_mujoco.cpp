// MuJoCo's constraint solver is a setting: Newton (the default) or conjugate gradients, which steps
// walls faster (docs/backends.md, "MuJoCo's solver"); each is held to Housner's rocking block
#include <catch2/catch.hpp>

#include <algorithm>

#include "cases/case_analysis.hpp"
#include "engine_scenes.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;
using namespace cairn::test;

TEST_CASE("mujoco: Newton and CG both rock reading B as Housner's block, and the run says which", "[engines]") {
    const auto names = engine_names();
    if (std::find(names.begin(), names.end(), "mujoco") == names.end()) return;   // not built in
    for (const char* solver : {"Newton", "CG"}) {
        const std::string text =
            shipped_scene_text("paper/rocking.toml") + "\n[backends.mujoco]\nsolver = \"" + solver + "\"\n";
        const Scene s = parse_scene(text, "<rocking, " + std::string(solver) + ">");
        INFO(solver);
        const auto run = sampled_run("mujoco", s, "rigid", 1e-4);
        // Housner's first impact and half cycle within 1 %, amplitudes within 2 % (the rigid
        // engines' tolerances; Newton measured +0.48 %, CG +0.58 % on the first amplitude)
        CHECK(check_judged(cases::analyse_case(s, run, cases::ContactKind{false})) >= 4);
        const auto b = build_backend("mujoco", s, "rigid");
        const auto notes = b->notes();
        CHECK(std::any_of(notes.begin(), notes.end(),
                          [&](const std::string& n) { return n.rfind("solver: " + std::string(solver) + ",", 0) == 0; }));
    }
    // a solver MuJoCo does not have is refused by name
    const Scene bad =
        parse_scene(shipped_scene_text("paper/rocking.toml") + "\n[backends.mujoco]\nsolver = \"cg\"\n", "<bad>");
    CHECK_THROWS_WITH(build_backend("mujoco", bad, "rigid"),
                      Catch::Contains("solver") && Catch::Contains("Newton, CG, PGS"));
}
