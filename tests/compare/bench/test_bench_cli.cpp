// end to end: a quick `cairn bench trade --cases impact` writes trade.csv and the bench section, and
// a rerun finds every point already kept by the run layer (the executable is built with the tests: scripts/test.sh)
#include <catch2/catch.hpp>

#include "app/cairn_process.hpp"
#include "bench/trade_point.hpp"

using namespace cairn;
using namespace cairn::test;

TEST_CASE("cairn bench trade --cases impact --quick: trade.csv, tables, resume", "[bench][app]") {
    const auto dir = fresh_dir("bench_trade_quick");
    const auto out = dir / "out";
    const auto first = run_cairn("bench trade --cases impact --quick --repeats 1 --quiet --out '" + out.string() + "'", dir);
    INFO(first.err);
    REQUIRE(first.exit_code == 0);
    const auto pts = bench::read_trade_csv((out / "trade.csv").string());
    REQUIRE(!pts.empty());
    bool dem = false;
    for (const auto& p : pts) {
        CHECK(p.case_name == "impact");
        dem = dem || p.variant == "dem-rigid";
        // the dem impact at a fraction of its critical step completes and is measured
        if (p.variant == "dem-rigid") CHECK(p.measured());
    }
    CHECK(dem);
    const std::string md = read_file(out / "bench.md");
    CHECK(md.find("Cheapest configuration per variant") != std::string::npos);
    CHECK(md.find("dem-rigid") != std::string::npos);

    const auto again = run_cairn("bench trade --cases impact --quick --repeats 1 --out '" + out.string() + "'", dir);
    REQUIRE(again.exit_code == 0);
    CHECK(again.err.find(std::to_string(pts.size()) + " points already in") != std::string::npos);
    CHECK(bench::read_trade_csv((out / "trade.csv").string()).size() == pts.size());
    CHECK(again.err.find("trade.resume") != std::string::npos);   // the run layer's resume log
}
