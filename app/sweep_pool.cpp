#include "sweep_pool.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "run/stop.hpp"

namespace cairn {

void run_sweep_pool(const std::vector<RunJob>& jobs, int threads,
                    const std::function<void(std::size_t, const JobOutcome&)>& done) {
    std::atomic<std::size_t> next{0};
    std::mutex report, ode;
    std::exception_ptr failure;   // ODE keeps global state: its runs take turns
    const int n = std::max(1, std::min<int>(threads, int(jobs.size())));
    auto worker = [&] {
#ifdef _OPENMP
        if (n > 1) omp_set_num_threads(1);   // jobs × threads never exceed the cores
#endif
        for (std::size_t j; !stop_requested() && (j = next++) < jobs.size();) {
            JobOutcome o;
            try {
                if (jobs[j].backend == "ode") {
                    std::lock_guard<std::mutex> g(ode);
                    o = execute_run(jobs[j]);
                } else {
                    o = execute_run(jobs[j]);
                }
            } catch (const std::exception& e) {   // a write error: the run counts as failed
                o.status = JobStatus::input_error;
                o.message = std::string("unexpected failure: ") + e.what();
            }
            std::lock_guard<std::mutex> g(report);
            if (failure) continue;
            try {
                done(j, o);
            } catch (...) {   // the first failure to record a result ends the pool, then propagates
                failure = std::current_exception();
                request_stop();
            }
        }
    };
    std::vector<std::thread> pool;
    for (int i = 0; i < n; ++i) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace cairn
