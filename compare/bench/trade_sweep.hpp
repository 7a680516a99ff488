#pragma once
/// `cairn bench trade`: the configurations each backend lets a user turn on the rocking and impact
/// cases (time step, contact stiffness, mesh and mass scheme, solver iterations), run on a pool of
/// threads with repeats, measured against the case's oracle, appended to trade.csv as they finish
/// (a rerun skips the keys already there).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend_info.hpp"
#include "bench/trade_point.hpp"

namespace cairn::bench {

/// How big a sweep.
enum class SweepSize {
    quick,      ///< two or three points per backend (tests)
    standard,   ///< the default: a few minutes on 2 cores
    full,       ///< finer grids of every knob
};

/// One configuration to run: its point (keys filled, results empty) and its scene.
struct TradeConfig {
    TradePoint point;
    Scene scene;                          ///< overrides applied, duration cut to the measured event
    std::string contact_mode = "rigid";   ///< RunOptions::contact_mode
};

/// the cases the trade knows: "rocking", "rocking_slender", "impact"
const std::vector<std::string>& trade_cases();

/// every configuration of `case_name` (scene file `scene_path`) for the given backends
std::vector<TradeConfig> trade_configs(const std::string& case_name, const std::string& scene_path,
                                       const std::vector<std::string>& backends, SweepSize size);

/// the error of a run against its case's oracle (compare/cases): |relative error| of the first
/// impact (rocking) or the larger of the bounce-period and peak-penetration errors (impact); NaN
/// and the reason in `metric` when the event was not reached
double trade_error(const Scene& scene, const std::vector<Sample>& samples, bool penalty, std::string& metric);

/// Options of a trade run.
struct TradeOptions {
    int repeats = 3;      ///< runs per point; the wall time is their median
    int jobs = 2;         ///< points at a time
    bool quiet = false;   ///< no progress lines
};

/// the run layer's resume log of the trade sweep writing `csv_path`: trade.resume beside it
std::string trade_resume_path(const std::string& csv_path);

/// run every configuration (through the run layer, resuming: a point kept in trade_resume_path()
/// by an earlier invocation is not run again) and write `csv_path` afresh, kept points first, each
/// finished point as it ends; returns every point. Runs of a backend that is not thread-safe never
/// overlap.
std::vector<TradePoint> run_trade(const std::vector<TradeConfig>& configs, const std::string& csv_path,
                                  const TradeOptions& options, const std::vector<BackendInfo>& backends);

}  // namespace cairn::bench
