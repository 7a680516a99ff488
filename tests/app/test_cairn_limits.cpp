// absurd input is refused before any work: exit 2, a message naming file, key and value, nothing
// written; an element that turns inside out stops the run as unstable (exit 3)
#include <catch2/catch.hpp>

#include "cairn_process.hpp"

namespace fs = std::filesystem;
using namespace cairn::test;
using Catch::Matchers::Contains;

namespace {
const std::string kRun = "run paper/stability --backend dem --quiet --out ";

// exit code 2, the message contains `what`, and no output directory was left
void refused(const std::string& args, const std::string& what, const std::string& name) {
    const fs::path dir = fresh_dir("limits_" + name);
    const auto r = run_cairn(kRun + (dir / "out").string() + " " + args, dir);
    CAPTURE(args, r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Contains(what));
    CHECK_FALSE(fs::exists(dir / "out"));
}
}  // namespace

TEST_CASE("cairn run refuses step and row counts beyond the limits", "[app][limits]") {
    refused("--set run.dt=1e-30", "stability.toml: run.duration = 0.5 s with run.dt = 1e-30 is 5e+29 steps", "dt");
    refused("--set contact.kn=1e300", "run.dt = auto gave 1.02e-149 s from the critical step", "kn");
    refused("--set run.dt=1e-7 --set run.output_interval=1e-7 --set run.duration=20",
            "is 2e+08 trajectory rows, beyond the limit of 1e+08", "rows");
}

TEST_CASE("cairn run refuses a given dt above the critical step unless --allow-unstable-dt", "[app][limits]") {
    refused("--set run.dt=0.1", "run.dt = 0.1: above the critical step 0.01107 s of backend dem", "unstable_dt");
    const fs::path dir = fresh_dir("limits_unstable_dt_allowed");
    const auto r = run_cairn(kRun + (dir / "out").string() + " --set run.dt=0.1 --set run.duration=0.3 --allow-unstable-dt", dir);
    CHECK(r.exit_code != 2);
}

TEST_CASE("cairn run refuses absurd meshes and grid spacings before allocating", "[app][limits]") {
    refused("--model deformable --set 'blocks.A.mesh.divisions=[1000,1000,1000]'",
            "blocks.A.mesh.divisions = [1000, 1000, 1000]: 1e+09 elements", "divisions");
    refused("--set contact.grid_spacing=1e-12", "contact.grid_spacing = 1e-12: 1e+24 hitting points on one face", "grid12");
    refused("--set contact.grid_spacing=1e-5", "contact.grid_spacing = 1e-05: 1e+10 hitting points on one face", "grid5");
    refused("--set contact.grid_spacing=1e-3", "contact.grid_spacing = 0.001: 1.2e+07 hitting points", "grid3");
    refused("--memory-budget 1KiB", "beyond the memory budget of 1 KiB", "budget");
}

TEST_CASE("cairn run refuses --set values with control characters or invalid UTF-8, naming the key", "[app][limits]") {
    // printf makes the bytes: the test shell need not understand $'...'
    refused("--set \"description=$(printf 'a\\001b')\"", "--set description = a\\x01b: the value contains a control character",
            "ctrl");
    refused("--set \"description=$(printf 'a\\377b')\"", "--set description = a\\xffb: the value contains invalid UTF-8",
            "utf8");
}

TEST_CASE("cairn run refuses a scene whose dotted key would overflow the parser's stack", "[app][limits]") {
    const fs::path dir = fresh_dir("limits_deep_key");
    {
        std::ofstream f(dir / "deep.toml");
        f << "a";
        for (int i = 0; i < 30000; ++i) f << ".a";   // ~60 KB: once exit 139 inside toml++
        f << " = 1\n";
    }
    const auto r = run_cairn("run " + (dir / "deep.toml").string() + " --backend dem --out " + (dir / "out").string(), dir);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Contains("deep.toml:1: a.a.a") && Contains("more than 32 parts"));
}

TEST_CASE("cairn run refuses overlapping blocks and names that break the CSV header", "[app][limits]") {
    refused("--set 'blocks.A.position=[0.2,0,0.1]'",
            "blocks.A.position = [0.2,0,0.1]: block A overlaps block B by 0.4 m at t = 0", "overlap");
    refused("--set 'probes.\"p,q\".block=\"A\"' --set 'probes.\"p,q\".corner=6'", "a name must not contain ','", "name");
}

TEST_CASE("a deformable block with young = 1e-300 stops as unstable when an element inverts", "[app][limits]") {
    const fs::path dir = fresh_dir("limits_inversion");
    const auto r = run_cairn(kRun + (dir / "out").string() +
                                 " --model deformable --set materials.stone.young=1e-300 --set run.duration=1",
                             dir);
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Contains("block A: element ") && Contains("turned inside out at t = "));
    CHECK(fs::exists(dir / "out" / "trajectory.partial.csv"));
}
