#pragma once
/// The local pool of a sweep: its runs on worker threads through execute_run. Kept in one small
/// place so that it can be routed through the project's run layer.

#include <cstddef>
#include <functional>
#include <vector>

#include "run_job.hpp"

namespace cairn {

/// run `jobs` on the run layer's pool (run_on_cores: at most `threads` at a time, runs × OpenMP
/// threads within the cores, runs of a backend that is not thread-safe never overlapping);
/// `done(i, outcome)` is called from a worker, one at a time, after job i; stops taking new jobs
/// once a stop is requested
void run_sweep_pool(const std::vector<RunJob>& jobs, int threads,
                    const std::function<void(std::size_t, const JobOutcome&)>& done);

}  // namespace cairn
