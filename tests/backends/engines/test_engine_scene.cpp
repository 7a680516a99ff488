// the reference engines refuse what they cannot represent, check their settings, and carry a wall
#include <catch2/catch.hpp>

#include <chrono>
#include <iostream>

#include "engine_scenes.hpp"
#include "error.hpp"
#include "registry.hpp"

using namespace cairn;
using namespace cairn::test;

TEST_CASE("reference engines: deformable blocks are refused by name", "[engines]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    CAPTURE(engine);
    Scene s = base_scene("deformable");
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    s.blocks[0].model = BlockModel::deformable;
    auto b = make_backend(engine);
    CHECK_THROWS_WITH(b->build(s, RunOptions{}),
                      Catch::Contains("backend " + engine + " cannot represent deformable block 'A'") &&
                          Catch::Contains("--model rigid"));
}

TEST_CASE("reference engines: settings tables are checked", "[engines]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    CAPTURE(engine);
    Scene s = base_scene("settings");
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    auto b = make_backend(engine);
    SECTION("an unknown key is named with its origin") {
        s.backend_settings[engine]["iteratoins"] = {10LL, "scene.toml:12"};
        CHECK_THROWS_WITH(b->build(s, RunOptions{}),
                          Catch::Contains("scene.toml:12") && Catch::Contains("'iteratoins'"));
    }
    SECTION("a scene key selects the matched contact mode, or is refused by an engine without it") {
        s.backend_settings[engine]["contact_mode"] = {std::string("matched"), "scene.toml:3"};
        if (!has_matched_mode(engine)) {
            CHECK_THROWS_WITH(b->build(s, RunOptions{}), Catch::Contains("matched") && Catch::Contains(engine));
            return;
        }
        b->build(s, RunOptions{});
        auto notes = b->notes();
        CHECK(std::find(notes.begin(), notes.end(), "contact_mode: matched") != notes.end());
    }
    SECTION("a bad contact mode is refused") {
        s.backend_settings[engine]["contact_mode"] = {std::string("soft"), "scene.toml:3"};
        CHECK_THROWS_WITH(b->build(s, RunOptions{}), Catch::Contains("scene.toml:3") && Catch::Contains("soft"));
    }
    SECTION("dt = auto takes the documented engine default and says so") {
        s.run.dt.reset();
        b->build(s, RunOptions{});
        CHECK(b->time_step() == 1e-4);
        bool said = false;
        for (const auto& n : b->notes()) said = said || n.find("dt = auto") != std::string::npos;
        CHECK(said);
    }
}

TEST_CASE("reference engines: a 10 x 30 brick wall builds and stands, or is refused", "[engines][wall]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    CAPTURE(engine);
    // running bond of 0.4 x 0.2 x 0.2 m bricks, 30 courses of 10, on a fixed base: 300 free blocks
    Scene s = base_scene("wall");
    s.run.dt = 1e-3;
    add_box(s, "base", Vec3(5.0, 1.0, 0.5), Vec3(0, 0, -0.25), true);
    for (int course = 0; course < 30; ++course)
        for (int i = 0; i < 10; ++i) {
            double x = -1.8 + 0.4 * i + (course % 2 ? 0.2 : 0.0);
            add_box(s, "b" + std::to_string(course) + "_" + std::to_string(i), Vec3(0.4, 0.2, 0.2),
                    Vec3(x, 0, 0.1 + 0.2 * course), false);
        }
    auto b = make_backend(engine);
    try {
        b->build(s, RunOptions{});
    } catch (const Error& e) {
        // a refusal must say why
        CHECK(std::string(e.what()).find("blocks") != std::string::npos);
        WARN(engine << " refuses the wall: " << e.what());
        return;
    }
    const int steps = 200;
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i)
        if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    WARN(engine << " wall: " << steps / seconds << " steps/s (dt 1e-3)");
    // after 0.2 s the wall still stands: the top course moved less than 5 mm
    Sample x = b->sample();
    double worst = 0.0;
    for (int i = 290; i < 300; ++i) {
        const Vec3 start_pos = s.blocks[i + 1].position;
        worst = std::max(worst, (x.blocks[i].position - start_pos).norm());
    }
    CAPTURE(worst);
    CHECK(worst < 5e-3);
}
