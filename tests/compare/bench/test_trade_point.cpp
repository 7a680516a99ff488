// the trade bench's logic on synthetic points: Pareto front, cheapest configuration reaching an
// error, trade.csv round trip and resume
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>

#include "bench/trade_point.hpp"
#include "bench/trade_sweep.hpp"
#include "error.hpp"

using namespace cairn;
using namespace cairn::bench;

namespace {

TradePoint pt(const std::string& variant, const std::string& knobs, double wall, double err,
              const std::string& status = "completed") {
    TradePoint p;
    p.case_name = "impact";
    p.backend = variant.substr(0, variant.find('-'));
    p.variant = variant;
    p.knobs = knobs;
    p.wall_seconds = wall;
    p.error = err;
    p.status = status;
    p.sim_seconds = 0.5;
    return p;
}

}  // namespace

TEST_CASE("bench trade: the Pareto front keeps only points no other beats on both wall time and error", "[bench]") {
    const std::vector<TradePoint> pts{
        pt("dem-rigid", "a", 1.0, 0.10),     // front: the cheapest
        pt("dem-rigid", "b", 2.0, 0.20),     // dominated by a
        pt("bullet-rigid", "c", 3.0, 0.01),  // front
        pt("ode-rigid", "d", 3.0, 0.02),     // same wall as c, worse error: dominated
        pt("ode-rigid", "e", 10.0, 0.001),   // front
        pt("ode-rigid", "f", 0.5, NAN),      // not measured: never on the front
        pt("mujoco-rigid", "g", 0.1, 1e-9, "unstable"),   // a blow-up is never on the front
    };
    const auto front = pareto_front(pts);
    REQUIRE(front.size() == 3);
    CHECK(pts[front[0]].knobs == "a");
    CHECK(pts[front[1]].knobs == "c");
    CHECK(pts[front[2]].knobs == "e");
}

TEST_CASE("bench trade: the cheapest configuration reaching a target, or none", "[bench]") {
    const std::vector<TradePoint> pts{
        pt("dem-rigid", "slow exact", 5.0, 0.0001), pt("dem-rigid", "fast 3 %", 0.1, 0.03),
        pt("dem-rigid", "mid 0.5 %", 1.0, 0.005),   pt("dem-rigid", "fast blow-up", 0.01, 0.0, "unstable"),
        pt("bullet-rigid", "only 2 %", 0.2, 0.02),
    };
    auto at = [&](const std::string& v, double t) {
        auto i = cheapest_reaching(pts, "impact", v, t);
        return i ? pts[*i].knobs : std::string("cannot");
    };
    CHECK(at("dem-rigid", 0.05) == "fast 3 %");
    CHECK(at("dem-rigid", 0.01) == "mid 0.5 %");
    CHECK(at("dem-rigid", 0.001) == "slow exact");
    CHECK(at("bullet-rigid", 0.05) == "only 2 %");
    CHECK(at("bullet-rigid", 0.01) == "cannot");
    CHECK(at("dem-rigid", 0.01) != "fast blow-up");
    CHECK(cheapest_reaching(pts, "rocking", "dem-rigid", 1.0) == std::nullopt);   // another case
    const auto best = most_accurate(pts, "impact", "bullet-rigid");
    REQUIRE(best);
    CHECK(pts[*best].knobs == "only 2 %");
}

TEST_CASE("bench trade: trade.csv round-trips and skips a row cut by an interruption", "[bench]") {
    auto p = pt("ode-rigid", "dt=1e-4 stepper=quickstep iterations=20", 0.25, 0.0123);
    p.error_metric = "bounce period, late";   // a comma inside a field is quoted
    std::string text = trade_csv_header() + "\n" + trade_csv_row(p) + "\n" + trade_csv_row(p).substr(0, 30);
    const auto back = parse_trade_csv(text);
    REQUIRE(back.size() == 1);
    CHECK(back[0].key() == p.key());
    CHECK(back[0].error_metric == p.error_metric);
    CHECK(back[0].error == Approx(0.0123));
    CHECK(back[0].wall_seconds == Approx(0.25));
}

TEST_CASE("bench trade: a rerun runs only the points the run layer has not kept", "[bench]") {
    const auto dir = std::filesystem::path(CAIRN_BINARY_DIR) / "test_scratch" / "compare" / "bench_resume";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string csv = (dir / "trade.csv").string();
    TradeConfig a, b, c;
    a.point = pt("dem-rigid", "kn=3e+07 dt_safety=0.1", 0.0, NAN);
    b.point = pt("bullet-matched", "kn=3e+07 dt=0.0001", 0.0, NAN);
    c.point = pt("ode-matched", "kn=3e+07 dt=0.0001", 0.0, NAN);
    std::vector<std::string> made;
    std::mutex made_lock;   // two points run at a time: their backends are made on two threads
    std::vector<BackendInfo> make;
    for (const std::string name : {"dem", "bullet", "ode"}) {
        BackendInfo b;
        b.name = name;
        b.make = [&made, &made_lock, name]() -> std::unique_ptr<Backend> {
            const std::lock_guard<std::mutex> hold(made_lock);
            made.push_back(name);
            throw Error("test: " + name + " refuses");
        };
        make.push_back(b);
    }
    // the first two points measured, as an interrupted sweep leaves them
    CHECK(run_trade({a, b}, csv, TradeOptions{3, 2, true}, make).size() == 2);
    CHECK(made.size() == 2);
    made.clear();
    const auto pts = run_trade({a, b, c}, csv, TradeOptions{3, 2, true}, make);
    // only the missing point ran (and was refused); the file holds all three, kept ones first
    REQUIRE(made.size() == 1);
    CHECK(made[0] == "ode");
    CHECK(pts.size() == 3);
    const auto again = read_trade_csv(csv);
    REQUIRE(again.size() == 3);
    CHECK(again[0].key() == a.point.key());
    CHECK(again[0].status == "refused");
    CHECK(again[2].key() == c.point.key());
    CHECK(again[2].status == "refused");
    // a second rerun has nothing left to do and writes the same rows
    made.clear();
    CHECK(run_trade({a, b, c}, csv, TradeOptions{3, 2, true}, make).size() == 3);
    CHECK(made.empty());
    const auto third = read_trade_csv(csv);
    REQUIRE(third.size() == 3);
    for (size_t i = 0; i < 3; ++i) CHECK(trade_csv_row(third[i]) == trade_csv_row(again[i]));
}
