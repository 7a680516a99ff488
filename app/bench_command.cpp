// `cairn bench trade | stability | wall | scale | all`: speed against accuracy, stability at the
// extremes, throughput side by side, cost per simulated second against model size (docs/bench.md)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "bench/bench_report.hpp"
#include "bench/scale_bench.hpp"
#include "bench/scale_large.hpp"
#include "bench/scale_pushover.hpp"
#include "bench/stability.hpp"
#include "bench/trade_sweep.hpp"
#include "bench/wall_bench.hpp"
#include "backend_option.hpp"
#include "commands.hpp"
#include "error.hpp"
#include "output/atomic_write.hpp"
#include "output/staged_dir.hpp"
#include "registry.hpp"
#include "run/stop.hpp"
#include "scene/scene_io.hpp"
#include "scenes.hpp"

namespace fs = std::filesystem;

namespace cairn {

namespace {

/// the backends of --backends (checked), in the registry's order
std::vector<std::string> bench_backends(const std::vector<std::string>& given) {
    const std::vector<std::string> asked = chosen_backends(given);
    std::vector<std::string> out;
    for (const auto& b : available_backends())
        if (std::find(asked.begin(), asked.end(), b.name) != asked.end()) out.push_back(b.name);
    return out;
}

std::unique_ptr<Backend> make(const std::string& name) { return make_backend(name); }

// the asked backends into `out`; false (the error printed) for an unknown name
bool backends_or_error(const BenchOptions& o, std::vector<std::string>& out) {
    try {
        out = bench_backends(o.backends);
        return true;
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return false;
    }
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
        const auto backends = bench_backends(o.backends);
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
        for (const auto& b : bench_backends(o.backends))
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
    if (!backends_or_error(o, backends)) return kExitBadInput;
    const auto rows = bench::run_wall(backends, bench::wall_setups(), o.courses, 10, o.wall_steps, o.repeats,
                                      available_backends(), o.quiet);
    write_text_atomic((fs::path(dir) / "wall.csv").string(), bench::wall_csv(rows));
    bench::write_bench_report(dir);
    for (const auto& r : rows)
        std::printf("wall [%s] %-7s %8.1f steps/s  x%.2f of Bullet's steps/s at the same dt  %s\n", r.setup.c_str(), r.backend.c_str(),
                    r.steps_per_second, r.ratio_to_bullet, r.status.substr(0, 60).c_str());
    std::printf("wall: %s/wall.csv; %.1f s wall\n", o.out_dir.c_str(), seconds_since(t0));
    return kExitOk;
}

/// the building-scale tower under El Centro on dem; writes scale_large.csv into `dir`
int scale_large(const BenchOptions& o, const std::string& dir) {
    GroundMotion record;
    try {
        const Scene column = load_scene(resolve_scene("earthquake/column_elcentro"), {});
        record = *column.ground_motion;
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    if (!o.quiet)
        std::fprintf(stderr, "scale --large: a tower of about %d bricks, %g s of El Centro on dem\n", o.large_blocks,
                     o.large_duration);
    auto b = make_backend("dem");
    const auto r = bench::run_large(*b, o.large_blocks, record, o.large_duration);
    write_text_atomic((fs::path(dir) / "scale_large.csv").string(), bench::large_csv(r));
    bench::write_bench_report(dir);
    std::printf("scale --large: %d bricks, %g s simulated in %lld steps of %.3g s (critical %.3g s): %.0f s wall "
                "(+%.0f s building), %.0f s per simulated s, %g s of record in %.2f h; peak %.0f MB; %.0f sub-contacts, "
                "%.0f ns per sub-contact and step; energy balance %s (%.2g); %s\n",
                r.blocks, r.duration, r.steps, r.dt, r.critical_step, r.wall_seconds, r.build_seconds, r.cost(),
                bench::kLargeRecordSeconds, r.cost() * bench::kLargeRecordSeconds / 3600.0, r.peak_mb, r.contacts,
                r.ns_per_contact(), r.energy_closed ? "closed" : "drifted", r.max_balance_error, r.status.c_str());
    if (r.status.rfind("unstable", 0) == 0) return kExitUnstable;   // its row is kept and says so
    return kExitOk;   // interrupted: bench_command keeps the previous results
}

/// writes into `dir` (the staging directory of o.out_dir)
int scale(const BenchOptions& o, const std::string& dir) {
    if (o.large) return scale_large(o, dir);
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::string> backends;
    if (!backends_or_error(o, backends)) return kExitBadInput;
    // the accuracy first: each backend's largest dt that settles a wall within 1 %
    const auto acc = bench::scale_accuracy(backends, {1e-3, 3e-4, 1e-4, 3e-5}, 0.01, make, o.quiet);
    // a backend that misses 1 % at every dt is timed at its largest completed one, and says so
    std::vector<double> dts;
    std::vector<bool> missed;
    for (const auto& b : backends) {
        const double dt = bench::reaching_dt(acc, b, 0.01);
        missed.push_back(!(dt > 0.0));
        dts.push_back(dt > 0.0 ? dt : bench::reaching_dt(acc, b, HUGE_VAL));
    }
    auto rows = bench::run_scale(backends, dts, o.scale_sizes, o.scale_steps, make, o.quiet);
    for (auto& r : rows)
        for (size_t i = 0; i < backends.size(); ++i)
            if (r.backend == backends[i] && missed[i] && r.status == "completed")
                r.status = "completed; no dt tried settles within 1 % (scale_accuracy.csv)";
    // the second accuracy measure: the pushover wall's a/g within 2 %, the cheapest setting per backend
    if (o.pushover) {
        const auto push = bench::scale_pushover(resolve_scene("structures/wall_pushover"), backends, 0.02, make, o.quiet);
        write_text_atomic((fs::path(dir) / "scale_pushover.csv").string(), bench::pushover_csv(push));
        for (const auto& b : backends) {
            const auto* p = bench::cheapest_reaching(push, b, 0.02);
            if (p)
                std::printf("scale pushover %-7s within 2 %%: %s, a/g %.4g against %.4g, %.3g s per simulated s\n", b.c_str(),
                            p->setting.c_str(), p->multiplier, p->reference, p->cost);
            else
                std::printf("scale pushover %-7s no setting tried reaches 2 %% (scale_pushover.csv)\n", b.c_str());
        }
    }
    write_text_atomic((fs::path(dir) / "scale_accuracy.csv").string(), bench::scale_accuracy_csv(acc));
    write_text_atomic((fs::path(dir) / "scale.csv").string(), bench::scale_csv(rows));
    bench::write_bench_report(dir);
    for (const auto& b : backends) {
        std::vector<double> n, cost;
        for (const auto& r : rows)
            if (r.backend == b && r.status.rfind("completed", 0) == 0) n.push_back(r.blocks), cost.push_back(r.cost);
        std::printf("scale %-7s dt %-7g", b.c_str(), dts[size_t(&b - backends.data())]);
        for (const auto& r : rows)
            if (r.backend == b) std::printf("  N %d: %.3g s/s %.0f MB", r.blocks, r.cost, r.peak_mb);
        std::printf("  cost ~ N^%.2f\n", bench::fitted_exponent(n, cost));
    }
    std::printf("scale: %s/scale.csv; %.1f s wall\n", o.out_dir.c_str(), seconds_since(t0));
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
    else if (which == "scale") benches = {&scale};
    else benches = {&wall, &trade, &stability};   // all: the wall first, on an otherwise idle machine
    for (auto* f : benches) {
        const int code = f(o, dir);
        if (code == kExitUnstable) staged->commit();   // the unstable run's row is kept
        if (code != kExitOk) return code;
        if (stop_requested()) return interrupted_keeping("bench results", o.out_dir);
    }
    staged->commit();
    if (which == "all") std::printf("bench: %s/bench.md, bench.html\n", o.out_dir.c_str());
    return kExitOk;
}

}  // namespace cairn
