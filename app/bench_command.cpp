// `cairn bench trade | stability | wall | all`: speed against accuracy, stability at the extremes,
// throughput side by side (docs/bench.md)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "bench/bench_report.hpp"
#include "bench/stability.hpp"
#include "bench/trade_sweep.hpp"
#include "bench/wall_bench.hpp"
#include "commands.hpp"
#include "error.hpp"
#include "output/atomic_write.hpp"
#include "output/staged_dir.hpp"
#include "registry.hpp"
#include "run/stop.hpp"
#include "scenes.hpp"

namespace fs = std::filesystem;

namespace cairn {

namespace {

std::vector<std::string> chosen_backends(const std::vector<std::string>& asked) {
    std::vector<std::string> out;
    for (const auto& b : available_backends())
        if (asked.empty() || std::find(asked.begin(), asked.end(), b.name) != asked.end()) out.push_back(b.name);
    for (const auto& a : asked) make_backend(a);   // an unknown name is an error
    return out;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// writes into `dir` (the staging directory of o.out_dir)
int trade(const BenchOptions& o, const std::string& dir) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<bench::TradeConfig> configs;
    const auto size = o.quick ? bench::SweepSize::quick : o.full ? bench::SweepSize::full : bench::SweepSize::standard;
    try {
        const auto backends = chosen_backends(o.backends);
        const auto cases = o.cases.empty() ? bench::trade_cases() : o.cases;
        for (const auto& c : cases) {
            if (std::find(bench::trade_cases().begin(), bench::trade_cases().end(), c) == bench::trade_cases().end())
                throw Error("--cases: unknown case '" + c + "' (rocking, rocking_slender, impact)");
            for (auto& cfg : bench::trade_configs(c, resolve_scene("paper/" + c), backends, size))
                configs.push_back(std::move(cfg));
        }
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    const auto pts = bench::run_trade(configs, (fs::path(dir) / "trade.csv").string(),
                                      {o.repeats, o.jobs, o.quiet}, available_backends());
    bench::write_bench_report(dir);
    std::printf("trade: %zu points in %s/trade.csv; %.1f s wall\n", pts.size(), o.out_dir.c_str(), seconds_since(t0));
    return kExitOk;
}

/// writes into `dir` (the staging directory of o.out_dir)
int stability(const BenchOptions& o, const std::string& dir) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<bench::StabilityConfig> configs;
    try {
        for (const auto& b : chosen_backends(o.backends))
            for (auto& c : bench::stability_configs(b, scenarios_dir(), available_backends(), o.long_steps)) configs.push_back(std::move(c));
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    const auto pts = bench::run_stability(configs, o.jobs, o.quiet, available_backends());
    write_text_atomic((fs::path(dir) / "stability.csv").string(), bench::stability_csv(pts));
    bench::write_bench_report(dir);
    std::printf("stability: %zu points in %s/stability.csv; %.1f s wall\n", pts.size(), o.out_dir.c_str(),
                seconds_since(t0));
    return kExitOk;
}

/// writes into `dir` (the staging directory of o.out_dir)
int wall(const BenchOptions& o, const std::string& dir) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::string> backends;
    try {
        backends = chosen_backends(o.backends);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    const auto rows = bench::run_wall(backends, bench::wall_setups(), o.courses, 10, o.wall_steps, o.repeats,
                                      available_backends(), o.quiet);
    write_text_atomic((fs::path(dir) / "wall.csv").string(), bench::wall_csv(rows));
    bench::write_bench_report(dir);
    for (const auto& r : rows)
        std::printf("wall [%s] %-7s %8.1f steps/s  x%.2f of Bullet  %s\n", r.setup.c_str(), r.backend.c_str(),
                    r.steps_per_second, r.ratio_to_bullet, r.status.substr(0, 60).c_str());
    std::printf("wall: %s/wall.csv; %.1f s wall\n", o.out_dir.c_str(), seconds_since(t0));
    return kExitOk;
}

}  // namespace

int bench_command(const std::string& which, const BenchOptions& o) {
    // the new results are built beside the old ones (carried over: a trade sweep resumes from its
    // trade.csv, and each bench keeps the others' files) and swapped in whole once complete
    std::unique_ptr<StagedDir> staged;
    try {
        staged = std::make_unique<StagedDir>(o.out_dir, true);
        staged->carry_over({}, StagedDir::Carry::copy);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    const std::string dir = staged->path().string();
    std::vector<int (*)(const BenchOptions&, const std::string&)> benches;
    if (which == "trade") benches = {&trade};
    else if (which == "stability") benches = {&stability};
    else if (which == "wall") benches = {&wall};
    else benches = {&wall, &trade, &stability};   // all: the wall first, on an otherwise idle machine
    for (auto* f : benches) {
        const int code = f(o, dir);
        if (code != kExitOk) return code;
        if (stop_requested()) return interrupted_keeping("bench results", o.out_dir);
    }
    staged->commit();
    if (which == "all") std::printf("bench: %s/bench.md, bench.html\n", o.out_dir.c_str());
    return kExitOk;
}

}  // namespace cairn
