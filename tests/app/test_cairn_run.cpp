// `cairn run` end to end: outputs, reruns, refusals and exit codes
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "cairn_process.hpp"

namespace fs = std::filesystem;
using namespace cairn::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {
const std::string kStability = "paper/stability --backend dem --set run.duration=0.05 --quiet";
}

TEST_CASE("cairn run twice gives byte-identical trajectories", "[app]") {
    const fs::path dir = fresh_dir("rerun");
    const auto a = run_cairn("run " + kStability + " --out " + (dir / "a").string(), dir);
    const auto b = run_cairn("run " + kStability + " --out " + (dir / "b").string(), dir);
    REQUIRE(a.exit_code == 0);
    REQUIRE(b.exit_code == 0);
    const std::string csv = read_file(dir / "a" / "trajectory.csv");
    CHECK_THAT(csv, StartsWith("t [s],"));
    CHECK_THAT(csv, Contains("A.x [m],A.y [m],A.z [m],A.qw [-],A.qx [-],A.qy [-],A.qz [-],E_kinetic [J]"));
    CHECK(csv == read_file(dir / "b" / "trajectory.csv"));

    const auto record = nlohmann::json::parse(read_file(dir / "a" / "run.json"));
    CHECK(record["status"] == "completed");
    CHECK(record["partial"] == false);
    CHECK(record["backend"] == "dem");
    CHECK(record["cairn_version"] == CAIRN_VERSION);
    CHECK(record["overrides"][0] == "run.duration=0.05");
    CHECK(record["parameters"]["run"]["duration"] == 0.05);
    CHECK(record["steps"].get<long long>() > 0);
}

TEST_CASE("cairn run refuses a non-empty directory unless --force", "[app]") {
    const fs::path dir = fresh_dir("force");
    const std::string out = " --out " + (dir / "run").string();
    REQUIRE(run_cairn("run " + kStability + out, dir).exit_code == 0);
    const std::string first = read_file(dir / "run" / "trajectory.csv");

    const auto refused = run_cairn("run " + kStability + out, dir);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.err, Contains("not empty") && Contains("--force"));
    CHECK(read_file(dir / "run" / "trajectory.csv") == first);

    const auto forced =
        run_cairn("run paper/stability --backend dem --set run.duration=0.02 -q --force" + out, dir);
    CHECK(forced.exit_code == 0);
    CHECK(read_file(dir / "run" / "trajectory.csv") != first);
}

TEST_CASE("cairn run with a bad scene exits 2 and writes nothing", "[app]") {
    const fs::path dir = fresh_dir("bad_scene");
    {
        std::ofstream f(dir / "bad.toml");
        f << "name = \"bad\"\n[run]\nduraton = 1\n";
    }
    const auto r = run_cairn("run " + (dir / "bad.toml").string() + " --backend dem --out " +
                             (dir / "out").string(), dir);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, StartsWith("error: ") && Contains("bad.toml:3") && Contains("duraton"));
    CHECK_FALSE(fs::exists(dir / "out"));

    const auto missing = run_cairn("run no/such/scene --backend dem --out " + (dir / "out").string(), dir);
    CHECK(missing.exit_code == 2);
    CHECK_THAT(missing.err, Contains("no scene 'no/such/scene'"));
    CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("cairn run with an unknown backend names the available ones", "[app]") {
    const fs::path dir = fresh_dir("bad_backend");
    const auto r = run_cairn("run paper/stability --backend nosuch --out " + (dir / "out").string(), dir);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Contains("unknown backend 'nosuch'") && Contains("dem"));
    CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("cairn run that goes unstable keeps a partial trajectory and exits 3", "[app]") {
    const fs::path dir = fresh_dir("unstable");
    const std::string out = " --out " + (dir / "run").string();
    REQUIRE(run_cairn("run " + kStability + out, dir).exit_code == 0);
    // dt far above the critical step of the contact spring (~1.1e-2 s for this scene): the
    // explicit integrator must blow up (--allow-unstable-dt: such a dt is refused otherwise)
    const auto r = run_cairn("run paper/stability --backend dem --set run.dt=0.05 --set run.duration=5"
                         " --allow-unstable-dt -q --force" + out, dir);
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Contains("unstable at t = ") && Contains("critical step"));
    CHECK(fs::exists(dir / "run" / "trajectory.partial.csv"));
    CHECK_FALSE(fs::exists(dir / "run" / "trajectory.csv"));   // the stale one is gone
    const auto record = nlohmann::json::parse(read_file(dir / "run" / "run.json"));
    CHECK(record["status"] == "unstable");
    CHECK(record["partial"] == true);
    CHECK_THAT(record["message"].get<std::string>(), Contains("critical step"));
}

TEST_CASE("cairn --version prints the version", "[app]") {
    const fs::path dir = fresh_dir("version");
    const auto r = run_cairn("--version", dir);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Contains(std::string("cairn ") + CAIRN_VERSION));
}
