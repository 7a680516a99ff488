// run.json: every field the issue asks for, from a run of the fake backend
#include <catch2/catch.hpp>

#include "../run/fake_backend.hpp"
#include "output/run_record.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

TEST_CASE("the run record holds the scene, versions, parameters and outcome", "[output]") {
    Scene scene = testing::ballistic_scene();
    testing::Faults f;
    f.unstable_at_step = 25;
    testing::FakeBackend backend(f);
    RunRequest request;
    request.scene_path = "scenes/ballistic.toml";
    request.overrides = {"contact.friction=0.4"};
    request.model_override = "rigid";
    request.options.contact_mode = "matched";
    const RunResult result = run_scene(backend, scene, request.options);
    const nlohmann::json j = run_record(scene, backend, result, request);

    CHECK(j["scene"]["name"] == "ballistic");
    CHECK(j["scene"]["path"] == "scenes/ballistic.toml");
    CHECK(j["backend"] == "fake");
    CHECK(j["engine_version"] == "fake 1.0");
    CHECK(j["cairn_version"] == CAIRN_VERSION);
    CHECK(j["overrides"] == nlohmann::json::array({"contact.friction=0.4"}));
    CHECK(j["model_override"] == "rigid");
    CHECK(j["contact_mode"] == "matched");
    CHECK(j["parameters"] == scene_to_json(scene));
    CHECK(j["dt"] == 1e-3);
    CHECK(j["critical_step"] == 2e-3);
    CHECK(j["steps"] == 25);
    CHECK(j["output_every"] == 10);
    CHECK(j["status"] == "unstable");
    CHECK(j["partial"] == true);
    CHECK(j["message"] == result.message);
    CHECK(j["energy_drift"] == false);
    CHECK(j.contains("wall_seconds"));
    CHECK(j.contains("max_balance_error"));
    CHECK(j["energy_gain"] == result.energy_gain);
    CHECK(j["energy_created"] == false);
    CHECK(j["final_time"] == result.samples.back().t);
    CHECK(j["final_energies"]["kinetic"] == result.samples.back().energy.kinetic);
    CHECK(j["notes"].is_array());
}
