#include "run/core_pool.hpp"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "run/stop.hpp"

namespace cairn {

int machine_cores() {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
    return std::max(1, int(std::thread::hardware_concurrency()));
}

int openmp_threads() {
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 0;
#endif
}

void set_openmp_threads(int n) {
#ifdef _OPENMP
    omp_set_num_threads(n);
#else
    (void)n;
#endif
}

CoreShare share_cores(std::size_t tasks, int jobs) {
    const int cores = machine_cores();
    CoreShare s;
    const int asked = jobs > 0 ? std::min(jobs, cores) : cores;
    s.workers = std::max(1, std::min<int>(asked, int(std::min<std::size_t>(tasks, std::size_t(cores)))));
    s.threads = std::max(1, cores / s.workers);
    return s;
}

void run_on_cores(std::size_t n, int jobs, const std::function<void(std::size_t)>& task,
                  const std::function<bool(std::size_t)>& exclusive) {
    const CoreShare share = share_cores(n, jobs);
    std::atomic<std::size_t> next{0};
    std::mutex serial, error_lock;
    std::exception_ptr error;
    auto worker = [&] {
#ifdef _OPENMP
        // this thread's OpenMP regions use its share of the cores; one thread: no team is formed
        omp_set_dynamic(0);
        omp_set_num_threads(share.threads);
#endif
        for (std::size_t i; !stop_requested() && (i = next++) < n;) {
            try {
                if (exclusive && exclusive(i)) {
                    std::lock_guard<std::mutex> lock(serial);
                    task(i);
                } else {
                    task(i);
                }
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_lock);
                if (!error) error = std::current_exception();
            }
        }
    };
    std::vector<std::thread> pool;
    for (int w = 0; w < share.workers; ++w) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace cairn
