// `cairn compare` end to end on a small column, and the command-line conventions (bare cairn,
// "did you mean" for commands, cases and scenes)
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "cairn_process.hpp"
#include "report/replay.hpp"

namespace fs = std::filesystem;
using namespace cairn::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

/// three 0.4 m cubes stacked on a fixed base, released from rest just touching
const char* kColumn = R"(description = "Three 0.4 m cubes stacked on a fixed base"
[run]
duration = 0.3
[materials.stone]
density = 2500
young = 30e9
poisson = 0.2
[contact]
kn = 3e8
ks = 3e8
friction = 0.6
damping_ratio = 0.2
[blocks.base]
size = [1.0, 1.0, 0.2]
position = [0.0, 0.0, -0.1]
material = "stone"
fixed = true
[blocks.drum1]
size = [0.4, 0.4, 0.4]
position = [0.0, 0.0, 0.2]
material = "stone"
[blocks.drum2]
size = [0.4, 0.4, 0.4]
position = [0.0, 0.0, 0.6]
material = "stone"
[blocks.drum3]
size = [0.4, 0.4, 0.4]
position = [0.0, 0.0, 1.0]
material = "stone"
)";

/// `text` written to dir/name; returns its path
fs::path write_scene(const fs::path& dir, const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
}

/// the row of a CSV whose first two fields are `a`,`b`, split
std::vector<std::string> row(const std::string& csv, const std::string& a, const std::string& b) {
    std::istringstream in(csv);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(a + "," + b + ",", 0) == 0) {
            std::vector<std::string> out;
            std::istringstream ls(line);
            std::string f;
            while (std::getline(ls, f, ',')) out.push_back(f);
            return out;
        }
    return {};
}

}  // namespace

TEST_CASE("cairn compare says when deformable blocks are soft against their joints", "[app][compare]") {
    // the column's drums at a tenth of their stiffness: kn·h/E = 3e8 · 0.4 / 3e9 = 0.04, past the
    // 0.005 below which a deformable block rocks as the rigid one (docs/validation.md)
    const fs::path dir = fresh_dir("compare_flexible");
    const fs::path scene = write_scene(dir, "column.toml", kColumn), out = dir / "report";
    const auto r = run_cairn("compare " + scene.string() + " --backends dem --model both -q --out " +
                                 out.string() + " --set materials.stone.young=3e9 --set run.duration=0.02",
                             dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(read_file(out / "report.md"),
               Contains("Deformable against rigid blocks: block drum1 is soft against its joints (kn·h/E = 0.04,"));
}

TEST_CASE("cairn compare runs a column on dem and Bullet and writes the comparison report", "[app][compare]") {
    const fs::path dir = fresh_dir("compare");
    const fs::path scene = write_scene(dir, "column.toml", kColumn), out = dir / "report";
    const auto r = run_cairn("compare " + scene.string() + " --backends dem,bullet --jobs 2 --out " +
                                 out.string(), dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    for (const char* v : {"dem-rigid", "dem-deformable", "bullet-rigid", "bullet-matched"}) CHECK_THAT(r.out, Contains(v));
    CHECK(fs::exists(out / "index.html"));
    const std::string md = read_file(out / "report.md");
    CHECK_THAT(md, Contains("## Differences from dem-rigid") && Contains("## Energy") && Contains("## Contacts") &&
                       Contains("## What each engine could not represent") && Contains("(#summary)"));
    // three free drums on each other: Bullet's iterative solver's creep is named (docs/backends.md)
    CHECK_THAT(md, Contains("| bullet | a structure held at rest | approximate |"));
    // kn·h/E = 3e8 · 0.4 / 3e10 = 0.004: the deformable drums are rigid against their joints
    CHECK_THAT(md, !Contains("Deformable against rigid blocks"));
    // per-variant histories with units in the header
    for (const char* v : {"dem-rigid", "bullet-rigid", "bullet-matched"}) {
        const std::string h = read_file(out / "data" / (std::string(v) + "_block1.csv"));
        CHECK_THAT(h, StartsWith("t [s],x [m],y [m],z [m],rotation angle [rad],speed [m/s]\n"));
        CHECK(fs::exists(out / "runs" / "column" / v / "trajectory.csv"));
    }
    // the difference table: every number finite
    const std::string diff = read_file(out / "differences.csv");
    REQUIRE_THAT(diff, StartsWith("block,variant,position RMS (m),"));
    for (const char* v : {"dem-deformable", "bullet-rigid", "bullet-matched"})
        for (const char* b : {"drum1", "drum2", "drum3"}) {
            const auto cells = row(diff, b, v);
            INFO(b << " " << v);
            REQUIRE(cells.size() == 10);
            for (size_t i = 2; i < cells.size(); ++i)
                if (cells[i] != "never") CHECK(std::isfinite(std::stod(cells[i])));
        }
    // the bottom drum stays at rest on both engines. dem's penalty springs under it carry the three
    // drums: static penetration d = 3 m g / (kn A) = 3 · 160 kg · 9.81 m/s² / (3e8 N/m³ · 0.16 m²)
    // = 9.8e-5 m, and released just touching the springs overshoot to at most 2d; Bullet's rigid
    // contact does not sink. So the centres may differ by at most 2d = 1.96e-4 m, and neither
    // diverges beyond 1 % of the 0.4 m edge nor turns by 0.01 rad.
    const auto rest = row(diff, "drum1", "bullet-rigid");
    REQUIRE(rest.size() == 10);
    CHECK(std::stod(rest[4]) < 1.96e-4);   // largest distance (m)
    CHECK(rest[3] == "never");             // position diverged at
    CHECK(rest[6] == "never");             // rotation diverged at
    // the 3-D replay of every variant beside the block figures, linked from both renderings
    const std::string html = read_file(out / "index.html");
    if (!cairn::replay_available()) {
        WARN("cairn is built without the 3-D replay: checking that the report says so");
        CHECK_FALSE(fs::exists(out / "replay.html"));
        CHECK_THAT(md, Contains("no 3-D replay: this cairn was built without it"));
        return;
    }
    const std::string page = read_file(out / "replay.html");
    CHECK_THAT(page, Contains("window.CAIRN_REPLAY = "));
    for (const char* v : {"dem-rigid", "dem-deformable", "bullet-rigid", "bullet-matched"})
        CHECK_THAT(page, Contains(std::string("\"label\":\"") + v + "\""));
    CHECK_THAT(html, Contains("<iframe src=\"replay.html\"") && Contains("<a href=\"replay.html\">"));
    CHECK_THAT(md, Contains("](replay.html)"));
    // the link sits in the Blocks section, before the energies
    CHECK(md.find("](replay.html)") > md.find("## Blocks"));
    CHECK(md.find("](replay.html)") < md.find("## Energy"));
}

TEST_CASE("cairn compare says how much dem's joints lower a shaken stack's overturning multiplier", "[app][compare]") {
    // the column of kColumn shaken along x: B/H = 0.4/1.2 about its base edge, which a joint of
    // springs kn reaches only as it opens while the column leans (docs/validation.md)
    const fs::path dir = fresh_dir("compare_stack");
    const std::string motion = "[ground_motion]\ntime = [0.0, 0.3]\nacceleration = [0.0, 0.5]\n";
    const fs::path shaken = write_scene(dir, "column.toml", kColumn + motion);
    const auto r = run_cairn("compare " + shaken.string() + " --backends dem,bullet --jobs 2 --out " +
                                 (dir / "report").string(), dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string md = read_file(dir / "report" / "report.md");
    CHECK_THAT(md, Contains("For this stack of 3 layers under the ground motion, joints of kn = 3e+08 N/m³ alone lower "
                            "the quasi-static overturning multiplier a/g from 0.3333 (rigid) to 0."));
    // without the ground motion (the first test's column) there is no such sentence
    const fs::path plain = write_scene(dir, "plain.toml", kColumn);
    const auto q = run_cairn("compare " + plain.string() + " --backends dem,bullet --jobs 2 --out " + (dir / "plain").string(), dir);
    REQUIRE(q.exit_code == 0);
    CHECK_THAT(read_file(dir / "plain" / "report.md"), !Contains("For this stack"));
}

TEST_CASE("bare cairn prints the usage and the commands, exit 2", "[app][cli]") {
    const fs::path dir = fresh_dir("bare");
    const auto r = run_cairn("", dir);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Contains("Usage: cairn") && Contains("compare") && Contains("validate") && Contains("run"));
}

TEST_CASE("mistyped commands, cases and scene names get a suggestion and exit 2", "[app][cli]") {
    const fs::path dir = fresh_dir("suggest");
    auto r = run_cairn("comapre x", dir);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Contains("unknown command 'comapre'") && Contains("did you mean 'compare'"));
    r = run_cairn("validate --cases rockng --backends dem --out " + (dir / "v").string(), dir);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Contains("rockng") && Contains("did you mean 'rocking'"));
    CHECK(!fs::exists(dir / "v"));
    r = run_cairn("compare paper/stabilty --backends dem --out " + (dir / "c").string(), dir);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Contains("did you mean 'paper/stability'"));
    // nothing close: no suggestion
    r = run_cairn("zzzzzzzzzz", dir);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, !Contains("did you mean"));
}

TEST_CASE("validate --help lists the cases", "[app][cli]") {
    const fs::path dir = fresh_dir("validate_help");
    const auto r = run_cairn("validate --help", dir);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("Usage: cairn validate") && Contains("rocking_slender") && Contains("friction_stick"));
}

TEST_CASE("cairn compare on a scene with a reference adds the verdicts and the analytic figure", "[app][compare]") {
    const fs::path dir = fresh_dir("compare_reference");
    const fs::path out = dir / "report";
    // 0.2 s holds three periods of the 58.5 ms swing, enough for the stability metrics
    const auto r = run_cairn("compare paper/stability --backends dem --model rigid --set run.duration=0.2 --out " +
                                 out.string(), dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string md = read_file(out / "report.md");
    CHECK_THAT(md, Contains("## Verdicts against the analytic reference") && Contains("| dem-rigid | equilibrium penetration |"));
    CHECK_THAT(md, !Contains("dem-deformable"));   // --model rigid
    CHECK(fs::exists(out / "figures" / "stability.png"));
    // one free block on a fixed one is no structure: the row of holding one at rest is left out
    const auto one = run_cairn("compare paper/stability --backends bullet --model rigid --set run.duration=0.05 --out " +
                                   (dir / "one").string(), dir);
    INFO(one.err);
    REQUIRE(one.exit_code == 0);
    const std::string one_md = read_file(dir / "one" / "report.md");
    CHECK_THAT(one_md, Contains("| bullet | elastic stick before slip |") && !Contains("a structure held at rest"));
}

TEST_CASE("cairn compare writes the same numbers for one run at a time and for two", "[app][compare]") {
    const fs::path dir = fresh_dir("compare_jobs");
    write_scene(dir, "column.toml", kColumn);
    // one at a time, dem uses every OpenMP thread; two at a time, one thread each
    for (const char* jobs : {"1", "2"}) {
        const auto r = run_cairn("compare " + (dir / "column.toml").string() + " --backends dem --set run.duration=0.1 --jobs " +
                                     jobs + " -q --out " + (dir / jobs).string(), dir);
        REQUIRE(r.exit_code == 0);
    }
    for (const char* f : {"differences.csv", "peaks.csv", "energy.csv", "data/dem-deformable_block3.csv"}) {
        INFO(f);
        CHECK(read_file(dir / "1" / f) == read_file(dir / "2" / f));
        CHECK(!read_file(dir / "1" / f).empty());
    }
}

TEST_CASE("dem warns of flutter on a pushed row without contact damping, on stderr and in the compare report",
          "[app][compare]") {
    // two 0.4 m cubes side by side, the first pushed along the row beyond friction: undamped
    // elastic-Coulomb joints flutter while they slide (docs/dem.md); ζ = 0.01 keeps them down
    const std::string row = R"([run]
duration = 0.02
[materials.stone]
density = 2600
young = 30e9
poisson = 0.2
[contact]
kn = 1e10
friction = 0.5
[blocks.A]
size = [0.4, 0.4, 0.4]
position = [0, 0, 0.2]
material = "stone"
[blocks.B]
size = [0.4, 0.4, 0.4]
position = [0.4, 0, 0.2]
material = "stone"
[blocks.G]
size = [3, 2, 0.4]
position = [0.4, 0, -0.2]
material = "stone"
fixed = true
[loads.push]
block = "A"
force = [2448.6, 0, 0]
)";
    const fs::path dir = fresh_dir("flutter_warning");
    {
        std::ofstream f(dir / "row.toml");
        f << row;
    }
    const std::string warning = "warning: undamped contact: elastic-Coulomb joints can flutter";
    const auto undamped = run_cairn("run " + (dir / "row.toml").string() + " --backend dem --out " + (dir / "u").string(), dir);
    REQUIRE(undamped.exit_code == 0);
    CHECK_THAT(undamped.err, Contains(warning));
    CHECK_THAT(read_file(dir / "u" / "run.json"), Contains(warning));
    const auto damped = run_cairn("run " + (dir / "row.toml").string() + " --backend dem --out " + (dir / "d").string() +
                                      " --set contact.damping_ratio=0.01", dir);
    REQUIRE(damped.exit_code == 0);
    CHECK_THAT(damped.err, !Contains(warning));
    // without a load nothing slides: no warning either
    {
        std::ofstream f(dir / "rest.toml");
        f << row.substr(0, row.find("[loads.push]"));
    }
    const auto resting = run_cairn("run " + (dir / "rest.toml").string() + " --backend dem --out " + (dir / "r").string(), dir);
    REQUIRE(resting.exit_code == 0);
    CHECK_THAT(resting.err, !Contains(warning));
    const auto compare = run_cairn("compare " + (dir / "row.toml").string() + " --backends dem,bullet --out " +
                                       (dir / "c").string(), dir);
    REQUIRE(compare.exit_code == 0);
    const std::string md = read_file(dir / "c" / "report.md");
    CHECK_THAT(md, Contains("Warnings the engines gave about their runs") &&
                       Contains("- dem-rigid: undamped contact: elastic-Coulomb joints can flutter"));
    CHECK_THAT(md, !Contains("- bullet-rigid: undamped contact"));
}
