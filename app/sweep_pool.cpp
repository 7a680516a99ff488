#include "sweep_pool.hpp"

#include <exception>
#include <mutex>

#include "registry.hpp"
#include "run/core_pool.hpp"
#include "run/stop.hpp"

namespace cairn {

void run_sweep_pool(const std::vector<RunJob>& jobs, int threads,
                    const std::function<void(std::size_t, const JobOutcome&)>& done) {
    std::mutex report;
    std::exception_ptr failure;
    run_on_cores(
        jobs.size(), threads,
        [&](std::size_t j) {
            JobOutcome o;
            try {
                o = execute_run(jobs[j]);
            } catch (const std::exception& e) {   // a write error: the run counts as failed
                o.status = JobStatus::failed;
                o.message = std::string("unexpected failure: ") + e.what();
            }
            std::lock_guard<std::mutex> g(report);
            if (failure) return;
            try {
                done(j, o);
            } catch (...) {   // the first failure to record a result ends the pool, then propagates
                failure = std::current_exception();
                request_stop();
            }
        },
        // a backend that is not thread-safe (its registry facts) runs one job at a time
        [&](std::size_t j) {
            for (const auto& b : available_backends())
                if (b.name == jobs[j].backend) return !b.thread_safe;
            return false;   // an unknown name: execute_run refuses it
        });
    if (failure) std::rethrow_exception(failure);
}

}  // namespace cairn
