// `cairn validate` end to end on a reduced set: summary rows, report files, exit codes
#include <catch2/catch.hpp>

#include <sstream>

#include "cairn_process.hpp"
#include "report/replay.hpp"

namespace fs = std::filesystem;
using namespace cairn::test;
using Catch::Matchers::Contains;

namespace {
/// the rows of summary.csv whose metric column (6th) is `metric`
std::vector<std::string> rows_with(const std::string& csv, const std::string& variant, const std::string& metric) {
    std::vector<std::string> out;
    std::istringstream in(csv);
    std::string line;
    while (std::getline(in, line))
        if (line.find("," + variant + ",") != std::string::npos && line.find("," + metric + ",") != std::string::npos)
            out.push_back(line);
    return out;
}
}  // namespace

TEST_CASE("cairn validate on stability with dem writes the summary, the report and the runs", "[app][validate]") {
    const fs::path dir = fresh_dir("validate");
    const fs::path out = dir / "val";
    // 0.2 s holds three periods of the 58.5 ms swing: enough for the period and the penetration
    const auto r = run_cairn("validate --cases stability --backends dem --set run.duration=0.2 -q --out " +
                                 out.string(), dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("stability") && Contains("dem-rigid") && Contains("dem-deformable"));
    const std::string csv = read_file(out / "summary.csv");
    CHECK(csv.rfind("case,variant,backend,contact_mode,model,metric,unit,value,reference,relative_error,"
                    "tolerance,pass,wall_seconds,status\n", 0) == 0);
    // rigid DEM: the three stability metrics pass (dem is within 0.06 % of mg/K, 2mg/K and 2π√(m/K)
    // at the paper's kn, against 1 % tolerances)
    for (const char* m : {"equilibrium penetration", "peak penetration", "period"}) {
        auto rows = rows_with(csv, "dem-rigid", m);
        INFO(m);
        REQUIRE(rows.size() == 1);
        CHECK_THAT(rows[0], Contains("stability,dem-rigid,dem,penalty,rigid,"));
        CHECK_THAT(rows[0], Contains(",pass,"));
    }
    // the deformable variant appears either with its metrics or as a run the backend cannot represent
    CHECK(csv.find("stability,dem-deformable,dem,penalty,deformable,") != std::string::npos);
    CHECK(fs::exists(out / "index.html"));
    CHECK(fs::exists(out / "report.md"));
    const std::string md = read_file(out / "report.md");
    CHECK_THAT(md, Contains("## Verdict") && Contains("## Conventions") && Contains("damping ratio ζ") &&
                       Contains("## Capability matrix"));
    // the verdict grid: cases down, variants across, each cell linking to its case's section
    CHECK_THAT(md, Contains("| case | dem-rigid | dem-deformable |") && Contains("| [stability](#stability) | [pass](#stability) |"));
    CHECK(fs::exists(out / "runs" / "stability" / "dem-rigid" / "trajectory.csv"));
    CHECK(fs::exists(out / "runs" / "stability" / "dem-rigid" / "run.json"));
    // the case's 3-D replay beside its figures (or a note when cairn is built without it)
    if (!cairn::replay_available()) {
        CHECK_FALSE(fs::exists(out / "replays"));
        CHECK_THAT(md, Contains("stability: no 3-D replay: this cairn was built without it"));
        return;
    }
    const std::string page = read_file(out / "replays" / "stability.html");
    CHECK_THAT(page, Contains("\"label\":\"dem-rigid\"") && Contains("window.CAIRN_REPLAY = "));
    CHECK_THAT(md, Contains("](replays/stability.html)"));
    CHECK(md.find("](replays/stability.html)") > md.find("## stability"));
    CHECK_THAT(read_file(out / "index.html"), Contains("<iframe src=\"replays/stability.html\""));
}

TEST_CASE("cairn validate rejects an unknown case or backend with exit code 2", "[app][validate]") {
    const fs::path dir = fresh_dir("validate_bad");
    auto r = run_cairn("validate --cases nosuchcase --out " + (dir / "v").string(), dir);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Contains("nosuchcase"));
    r = run_cairn("validate --backends nosuchengine --out " + (dir / "v").string(), dir);
    CHECK(r.exit_code == 2);
    CHECK_FALSE(fs::exists(dir / "v" / "summary.csv"));
}

TEST_CASE("cairn validate reports a variant the backend refuses and still writes the report", "[app][validate]") {
    const fs::path dir = fresh_dir("validate_refused");
    if (run_cairn("list", dir).out.find("mujoco") == std::string::npos) return;   // not built here
    // MuJoCo's matched contact is calibrated for the elliptic cone only: a pyramid is refused at build
    const auto r = run_cairn("validate --cases stability --backends dem,mujoco --set run.duration=0.1 "
                             "--set backends.mujoco.cone=pyramidal -q --out " + (dir / "v").string(), dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("mujoco-matched") && Contains("cannot represent"));
    const std::string csv = read_file(dir / "v" / "summary.csv");
    auto rows = rows_with(csv, "mujoco-matched", "run");
    REQUIRE(rows.size() == 1);
    CHECK_THAT(rows[0], Contains("cannot represent: mujoco:"));
    CHECK(rows_with(csv, "dem-rigid", "period").size() == 1);   // the other runs went on
    CHECK(fs::exists(dir / "v" / "index.html"));
}

TEST_CASE("cairn validate judges each rocking variant against the reference that models it", "[app][validate]") {
    const fs::path dir = fresh_dir("validate_rocking");
    if (run_cairn("list", dir).out.find("bullet") == std::string::npos) return;   // not built here
    // 2.3 s: past the second impact (2.15 s), so the first swing is complete
    const auto r = run_cairn("validate --cases rocking --backends dem,bullet --set run.duration=2.3 -q --out " +
                                 (dir / "v").string(), dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string csv = read_file(dir / "v" / "summary.csv");
    // dem: the spring block (same springs, own integrator) — measured within 0.2 % on both variants
    for (const char* v : {"dem-rigid", "dem-deformable"}) {
        auto rows = rows_with(csv, v, "amplitude after 1st impact");
        INFO(v);
        REQUIRE(rows.size() == 1);
        CHECK_THAT(rows[0], Contains(",pass,"));
    }
    // Bullet's rigid contact: Housner's impact (within 0.25 % in docs/validation.md)
    auto rigid = rows_with(csv, "bullet-rigid", "amplitude after 1st impact");
    REQUIRE(rigid.size() == 1);
    CHECK_THAT(rigid[0], Contains(",pass,"));
    // Bullet's matched contact: no reference models its impact: not comparable, with the reason
    auto matched = rows_with(csv, "bullet-matched", "amplitude after 1st impact");
    REQUIRE(matched.size() == 1);
    CHECK_THAT(matched[0], Contains("not comparable: no reference models it"));
}
