// sweep plans: what is refused (file, key, value named), and the expansion into runs
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>

#include "error.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runs.hpp"

namespace fs = std::filesystem;
using namespace cairn;
using namespace cairn::sweep;
using Catch::Matchers::Contains;

namespace {

fs::path scratch(const std::string& name) {
    const auto d = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "compare" / "sweep" / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

/// a plan file in `dir` naming the shipped column scene, with `body` after the common keys
std::string write_plan(const fs::path& dir, const std::string& body) {
    const auto p = dir / "plan.toml";
    std::ofstream(p) << "scene = \"" << CAIRN_SOURCE_DIR << "/scenarios/earthquake/column_elcentro.toml\"\n" << body;
    return p.string();
}

std::string resolve(const std::string& s) {
    if (fs::is_regular_file(s)) return s;
    throw Error("no scene '" + s + "'");
}

std::string error_of(const std::string& path) {
    try {
        read_sweep_plan(path, resolve);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

const char* kRecords = R"(
[records.elcentro]
file = ")" CAIRN_SOURCE_DIR R"(/scenarios/data/elcentro_1940_ns.csv"
[records.pulse]
pulse = "sine"
frequency = 2.0
)";

}  // namespace

TEST_CASE("sweep plans with bad keys or values are refused naming the file, key and value", "[sweep][plan]") {
    const auto d = scratch("refused");
    const std::string base = "backends = [\"bullet\"]\n";
    CHECK_THAT(error_of(write_plan(d, base + "colour = 3\n")), Contains("plan.toml") && Contains("colour"));
    CHECK_THAT(error_of(write_plan(d, "backends = [\"bul let\"]\n")), Contains("backends") && Contains("bul let"));
    CHECK_THAT(error_of(write_plan(d, "backends = [\"ode-deformable\"]\n")),
               Contains("backends") && Contains("ode-deformable") && Contains("variant"));
    CHECK_THAT(error_of(write_plan(d, base + "intensities = [0.1, -0.2]\n")),
               Contains("intensities[1]") && Contains("-0.2"));
    CHECK_THAT(error_of(write_plan(d, base + "repeats = 1000\n")), Contains("repeats") && Contains("1000"));
    CHECK_THAT(error_of(write_plan(d, base + "kind = \"fragility\"\n")), Contains("needs intensities"));
    CHECK_THAT(error_of(write_plan(d, base + "[records.a]\npulse = \"square\"\nfrequency = 1.0\n")),
               Contains("records.a.pulse") && Contains("square"));
    CHECK_THAT(error_of(write_plan(d, base + "[records.a]\nfile = \"nowhere.csv\"\n")),
               Contains("records.a.file") && Contains("no such file"));
    CHECK_THAT(error_of(write_plan(d, base + "[records.\"a b\"]\npulse = \"sine\"\nfrequency = 1.0\n")),
               Contains("a name of 1 to 64"));
    CHECK_THAT(error_of(write_plan(d, base + "[axes]\n\"contact.friction\" = 0.5\n")),
               Contains("contact.friction") && Contains("array"));
    // bounded: an expansion past the run limit is refused before anything is expanded
    std::string big = base + "intensities = [";
    for (int i = 1; i <= 1000; ++i) big += std::to_string(i * 0.01) + (i < 1000 ? "," : "]\n");
    big += "[axes]\n\"contact.friction\" = [";
    for (int i = 1; i <= 101; ++i) big += "0." + std::to_string(i + 100) + (i < 101 ? "," : "]\n");
    CHECK_THAT(error_of(write_plan(d, big)), Contains("101000 runs") && Contains("limit"));
    // an oversized file is refused before parsing
    {
        std::ofstream(d / "huge.toml") << std::string(kMaxPlanBytes + 10, '#');
        CHECK_THAT(error_of((d / "huge.toml").string()), Contains("more than"));
    }
}

TEST_CASE("a plan expands into runs with stable ids, shards partition them", "[sweep][plan]") {
    const auto d = scratch("expand");
    const auto plan = read_sweep_plan(
        write_plan(d, std::string("backends = [\"bullet\", \"ode\"]\nintensities = [0.1, 0.2, 0.3]\n[set]\n"
                                  "\"run.duration\" = 1.0\n[axes]\n\"contact.friction\" = [0.6, 0.8]\n") +
                          kRecords),
        resolve);
    const auto sweep = expand_sweep(plan, (d / "records").string());
    // 2 backends × 2 records × 3 intensities × 2 friction values
    REQUIRE(sweep.runs.size() == 24);
    std::set<std::string> ids;
    for (const auto& r : sweep.runs) ids.insert(r.id);
    CHECK(ids.size() == 24);
    // the same plan expanded again (elsewhere) gives the same ids and manifest
    const auto again = expand_sweep(plan, (d / "other").string());
    CHECK(sweep_manifest(again) == sweep_manifest(sweep));
    // the scale gives the intensity: El Centro peaks at 0.3188 g in the shipped file
    const auto& r0 = sweep.runs[0];
    CHECK(r0.record == "elcentro");
    CHECK(r0.scale * 0.3188 == Approx(0.1).epsilon(1e-3));
    // the pulse's file has unit peak, so its scale is the intensity itself
    for (const auto& r : sweep.runs)
        if (r.record == "pulse") CHECK(r.scale == Approx(r.intensity).epsilon(1e-12));
    CHECK(fs::exists(d / "records" / "pulse.csv"));
    // the column's overturning angle, atan(0.3 / 1.5)
    CHECK(r0.overturn_angle == Approx(std::atan(0.2)));
    CHECK(r0.block == "A");
    // shards: every run in exactly one of 5
    std::multiset<std::string> seen;
    for (int i = 0; i < 5; ++i)
        for (const auto& r : shard_of(sweep.runs, i, 5)) seen.insert(r.id);
    CHECK(seen.size() == 24);
    CHECK(std::set<std::string>(seen.begin(), seen.end()) == ids);
}

TEST_CASE("a bad scene key in a plan fails at expansion, before any run", "[sweep][plan]") {
    const auto d = scratch("badkey");
    const auto plan = read_sweep_plan(write_plan(d, "backends = [\"bullet\"]\n[set]\n\"contact.fricton\" = 0.5\n"), resolve);
    CHECK_THROWS_WITH(expand_sweep(plan, (d / "records").string()), Contains("fricton"));
}

TEST_CASE("backend variants split into backend, contact mode and block model", "[sweep][plan]") {
    CHECK(backend_variant("bullet").backend == "bullet");
    CHECK(backend_variant("bullet").contact == "rigid");
    CHECK(backend_variant("mujoco-matched").contact == "matched");
    CHECK(backend_variant("mujoco-matched").backend == "mujoco");
    CHECK(backend_variant("dem-deformable").model == "deformable");
    CHECK(backend_variant("dem-rigid").model == "rigid");
    CHECK(backend_variant("ode-rigid").model.empty());
    CHECK_THROWS_AS(backend_variant("dem-matched"), Error);
}

TEST_CASE("synthetic pulses have unit peak and come back to rest", "[sweep][plan]") {
    RecordSpec sine;
    sine.pulse = "sine";
    sine.frequency = 2.0;
    const std::string csv = pulse_csv(sine);
    CHECK_THAT(csv, Contains("not a recorded ground motion"));
    CHECK_THAT(csv, Contains("\n0.125,1\n"));     // sin(2π·2·0.125) = 1: the peak, a quarter period in
    CHECK_THAT(csv, Contains("\n0.5,0\n"));       // one period of 0.5 s, ending at rest
}
