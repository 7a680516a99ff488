// `cairn list` and `cairn run-all`, on a scenarios directory of the test's own ($CAIRN_SCENARIOS)
#include <catch2/catch.hpp>

#include "cairn_process.hpp"

namespace fs = std::filesystem;
using namespace cairn::test;
using Catch::Matchers::Contains;

namespace {

// a short version of paper/stability
const char* kTinyScene = R"(description = "tiny: a cube resting on a cube"
[run]
duration = 0.02
[materials.stone]
density = 2600
young = 30e9
poisson = 0.2
[contact]
kn = 3e7
ks = 3e7
friction = 0.6
[blocks.A]
size = [1.0, 1.0, 1.0]
position = [0.0, 0.0, 0.5]
material = "stone"
[blocks.B]
size = [1.0, 1.0, 1.0]
position = [0.0, 0.0, -0.5]
material = "stone"
fixed = true
)";

/// a scenarios dir holding sub/tiny.toml (and sub/broken.toml if asked); returns the env prefix
std::string scenarios(const fs::path& dir, bool with_broken) {
    fs::create_directories(dir / "scenes" / "sub");
    std::ofstream(dir / "scenes" / "sub" / "tiny.toml") << kTinyScene;
    if (with_broken) std::ofstream(dir / "scenes" / "sub" / "broken.toml") << "[run]\nduraton = 1\n";
    return "CAIRN_SCENARIOS='" + (dir / "scenes").string() + "'";
}

}  // namespace

TEST_CASE("cairn list shows the scenes with their description and the backends", "[app]") {
    const fs::path dir = fresh_dir("list");
    const auto r = run_cairn("list", dir, scenarios(dir, true));
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("sub/tiny") && Contains("tiny: a cube resting on a cube"));
    CHECK_THAT(r.out, Contains("sub/broken") && Contains("cannot load") && Contains("duraton"));
    CHECK_THAT(r.out, Contains("dem:"));
    // every backend states each feature as exact, approximate or none
    CHECK_THAT(r.out, Contains("exact"));
}

TEST_CASE("cairn run resolves a scene name in $CAIRN_SCENARIOS", "[app]") {
    const fs::path dir = fresh_dir("resolve");
    const auto r = run_cairn("run sub/tiny --backend dem -q --out " + (dir / "out").string(), dir,
                         scenarios(dir, false));
    CHECK(r.exit_code == 0);
    CHECK(fs::exists(dir / "out" / "trajectory.csv"));
    CHECK_THAT(read_file(dir / "out" / "run.json"), Contains("tiny.toml"));
}

TEST_CASE("cairn run-all runs every scene into out/<scene>/<backend>", "[app]") {
    const fs::path dir = fresh_dir("run_all");
    const std::string env = scenarios(dir, false);
    const std::string args = "run-all -q --backends dem --out " + (dir / "out").string();
    const auto r = run_cairn(args, dir, env);
    CHECK(r.exit_code == 0);
    CHECK(fs::exists(dir / "out" / "sub" / "tiny" / "dem" / "trajectory.csv"));
    CHECK(fs::exists(dir / "out" / "sub" / "tiny" / "dem" / "run.json"));
    CHECK_THAT(r.out, Contains("sub/tiny") && Contains("completed"));
    // a second run-all replaces its own outputs
    CHECK(run_cairn(args, dir, env).exit_code == 0);
}

TEST_CASE("cairn run-all fails when a scene does not load, after running the others", "[app]") {
    const fs::path dir = fresh_dir("run_all_broken");
    const auto r = run_cairn("run-all -q --backends dem --out " + (dir / "out").string(), dir,
                         scenarios(dir, true));
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Contains("FAILED") && Contains("duraton"));
    CHECK(fs::exists(dir / "out" / "sub" / "tiny" / "dem" / "trajectory.csv"));
}

TEST_CASE("cairn run-all refuses an unknown backend before running", "[app]") {
    const fs::path dir = fresh_dir("run_all_backend");
    const auto r = run_cairn("run-all -q --backends dem,nosuch --out " + (dir / "out").string(), dir,
                         scenarios(dir, false));
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Contains("unknown backend 'nosuch'"));
    CHECK_FALSE(fs::exists(dir / "out"));
}
