#pragma once
/// Runs the points of a bench on a pool of threads: each point's scene on its backend, repeated for
/// a median wall time, every failure kept as a result (refused, failed, unstable) and never thrown.

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "run/runner.hpp"

namespace cairn::bench {

/// One run to make.
struct PoolJob {
    std::string backend;                 ///< registry name
    std::string label;                   ///< for progress lines
    const Scene* scene = nullptr;        ///< ready to run (not owned)
    std::string contact_mode = "rigid";  ///< RunOptions::contact_mode
};

/// What one job gave.
struct PoolResult {
    std::string outcome;        ///< "completed", "unstable", "refused" (cairn::Error), "failed"
    std::string message;        ///< why it was not completed
    RunResult result;           ///< of the first repeat (runs are deterministic)
    double median_wall = 0.0;   ///< median wall time of the repeats, s (one run when unstable)
};

/// Options of the pool.
struct PoolOptions {
    int repeats = 3;       ///< runs per job
    int jobs = 2;          ///< threads
    bool quiet = false;    ///< no progress lines
    std::string tag;       ///< progress prefix
};

/// median of the values (NaN when empty)
double median(std::vector<double> v);

/// run every job; `done(j, result, lock)` is called from a worker for each finished job, with a
/// mutex the callback may lock to write shared outputs. Jobs on "ode" never overlap.
void run_pool(const std::vector<PoolJob>& jobs, const PoolOptions& options,
              const std::function<std::unique_ptr<Backend>(const std::string&)>& make,
              const std::function<void(size_t, const PoolResult&, std::mutex&)>& done);

}  // namespace cairn::bench
