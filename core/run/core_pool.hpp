#pragma once
/// The one pool of cairn: tasks on worker threads that share the machine's cores. The pool owns
/// the cores: workers × OpenMP threads per worker never exceed them, and each worker's OpenMP
/// regions are told how many threads they may use (one worker per core: no team at all, so no
/// thread spins waiting for another job's core).

#include <cstddef>
#include <functional>

namespace cairn {

/// the cores this process may run on (its CPU affinity), at least 1
int machine_cores();

/// How a pool shares the cores.
struct CoreShare {
    int workers = 1;   ///< tasks at a time
    int threads = 1;   ///< OpenMP threads of each task; workers × threads ≤ the cores
};

/// the share for `tasks` tasks with at most `jobs` at a time (0 or more than the cores: one per core)
CoreShare share_cores(std::size_t tasks, int jobs);

/// the OpenMP threads a parallel region started on the calling thread would use; 0 when cairn is
/// built without OpenMP
int openmp_threads();

/// set the OpenMP threads of the parallel regions the calling thread starts (n ≥ 1); nothing when
/// cairn is built without OpenMP
void set_openmp_threads(int n);

/// run task(i) for every i in [0, n) on share_cores(n, jobs).workers threads, each with its OpenMP
/// thread count set to the share's threads; tasks for which exclusive(i) is true never overlap each
/// other (a backend that is not thread-safe); once a stop is requested (run/stop.hpp) no new task
/// starts. A task's exception ends that task only and is rethrown here after all have ended.
void run_on_cores(std::size_t n, int jobs, const std::function<void(std::size_t)>& task,
                  const std::function<bool(std::size_t)>& exclusive = {});

}  // namespace cairn
