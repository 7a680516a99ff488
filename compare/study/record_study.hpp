#pragma once
/// The record study (docs/studies.md): one block under a ground-motion record on every backend,
/// each θ(t) against the rocking oracle's, the time they part beyond 5 % of α, and the chaos
/// yardstick: how soon the oracle parts from itself when r or the record changes by 1 %.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "scene/scene_io.hpp"

namespace cairn::study {

/// What to run.
struct RecordSetup {
    std::string scene_text;            ///< TOML of the block on its base, with its [ground_motion]
    std::string scene_source;          ///< a path, or "--block"
    std::vector<Override> overrides;   ///< --set, applied to every backend scene
    std::vector<std::string> backends;
    int jobs = 2;                      ///< runs at a time
    /// backends whose runs must not overlap (not thread-safe), by name; empty = none
    std::function<bool(const std::string&)> exclusive;
    bool quiet = false;
    double output_interval = 0.005;    ///< s between compared samples
};

/// One θ(t) history.
struct History {
    std::string method;             ///< a backend, "oracle", "oracle r+1%", "oracle record+1%"
    std::vector<double> theta;      ///< rad at RecordResult::times (NaN after a failed run's end)
    double parting = NAN;           ///< s: first time |θ − θ_oracle| > 5 % of α (NaN: never)
    double max_theta = 0.0;         ///< rad
    double overturn_time = NAN;     ///< s: |θ| passed π/3 (backends) or π/2 (oracle); NaN: never
    std::string status = "completed";
};

/// The study's result.
struct RecordResult {
    double b = 0.0, h = 0.0, alpha = 0.0, p = 0.0, r = 0.0, duration = 0.0;
    std::string record;                 ///< where the record came from
    std::vector<double> times;          ///< s
    std::vector<History> histories;     ///< oracle first, its two yardsticks, then the backends
};

/// the first time (s) two histories differ by more than `limit` (rad); NaN if never
double parting_time(const std::vector<double>& times, const std::vector<double>& a, const std::vector<double>& b,
                    double limit);

/// run the backends (on a pool) and the oracle with its yardsticks
using RecordBackendMaker = std::function<std::unique_ptr<Backend>(const std::string&)>;
RecordResult run_record_study(const RecordSetup& s, const RecordBackendMaker& make);

/// write DIR/record.csv, figures, DIR/record.md and .html
void write_record_study(const std::string& dir, const RecordResult& r);

}  // namespace cairn::study
