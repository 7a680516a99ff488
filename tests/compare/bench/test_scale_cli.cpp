// end to end: `cairn bench scale` on dem and a small wall writes scale_accuracy.csv, scale.csv and
// the report section (the executable is built with the tests: scripts/test.sh)
#include <catch2/catch.hpp>

#include "app/cairn_process.hpp"
#include "bench/scale_bench.hpp"
#include "bench/bench_report.hpp"
#include "bench/scale_large.hpp"

#include <cmath>

using namespace cairn;
using namespace cairn::test;

TEST_CASE("cairn bench scale --backends dem --sizes 100: accuracy, cost rows, report section", "[bench][app]") {
    const auto dir = fresh_dir("bench_scale_small");
    const auto out = dir / "out";
    const auto r = run_cairn("bench scale --backends dem --sizes 100 --steps 2 --no-pushover --quiet --out '" + out.string() + "'", dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto acc = bench::parse_scale_accuracy_csv(bench::read_whole((out / "scale_accuracy.csv").string()));
    // 1e-3 s is above dem's critical step at kn = 3e9 and refused; 3e-4 s settles within 1 %
    REQUIRE(acc.size() == 2);
    CHECK(acc[0].status.rfind("refused", 0) == 0);
    CHECK(acc[1].status == "completed");
    CHECK(std::abs(acc[1].error) < 0.01);
    const auto rows = bench::parse_scale_csv(bench::read_whole((out / "scale.csv").string()));
    REQUIRE(rows.size() == 1);
    CHECK(rows[0].backend == "dem");
    CHECK(rows[0].blocks == 104);   // 8 bricks per course, 13 courses
    CHECK(rows[0].dt == 3e-4);
    CHECK(rows[0].status == "completed");
    CHECK(rows[0].cost == Approx(rows[0].step_seconds / rows[0].dt));
    const std::string md = bench::read_whole((out / "bench.md").string());
    CHECK(md.find("Cost against model size at equal accuracy") != std::string::npos);
}

TEST_CASE("cairn bench scale refuses a wall size out of range", "[bench][app]") {
    const auto dir = fresh_dir("bench_scale_bad");
    const auto r = run_cairn("bench scale --sizes 5 --out '" + (dir / "out").string() + "'", dir);
    CHECK(r.exit_code != 0);
    CHECK(r.err.find("--sizes") != std::string::npos);
}

TEST_CASE("cairn bench scale --large --large-blocks 100: the tower under El Centro runs stable with closed energy", "[bench][app]") {
    // the path of the 10⁴-brick run at 100 bricks and 0.05 s: the shipped record, dem, dt auto
    const auto dir = fresh_dir("bench_scale_large");
    const auto out = dir / "out";
    const auto r = run_cairn("bench scale --large --large-blocks 100 --large-duration 0.05 --quiet --out '" +
                                 out.string() + "'", dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto row = bench::parse_large_csv(bench::read_whole((out / "scale_large.csv").string()));
    CHECK(row.blocks == 100);
    CHECK(row.status == "completed");
    // dt auto: the default safety 0.1 of the contact critical step, and whole steps to 0.05 s
    CHECK(row.dt == Approx(0.1 * row.critical_step).epsilon(1e-6));
    CHECK(row.steps == (long long)std::ceil(0.05 / row.dt - 1e-9));
    // the runner's energy check: balance error within its 1 % drift bound of the motion's energy
    CHECK(row.energy_closed);
    CHECK(row.max_balance_error < 0.01);
    // bricks settle onto each other: every bed joint has at least one active sub-contact
    CHECK(row.contacts >= 100);
    const std::string md = bench::read_whole((out / "bench.md").string());
    CHECK(md.find("A building-scale model under El Centro") != std::string::npos);
}

TEST_CASE("cairn bench scale refuses a large tower or duration out of range", "[bench][app]") {
    const auto dir = fresh_dir("bench_scale_large_bad");
    auto r = run_cairn("bench scale --large --large-blocks 5 --out '" + (dir / "out").string() + "'", dir);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--large-blocks") != std::string::npos);
    r = run_cairn("bench scale --large --large-duration 0 --out '" + (dir / "out").string() + "'", dir);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--large-duration") != std::string::npos);
}
