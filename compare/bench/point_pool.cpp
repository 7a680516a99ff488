#include "bench/point_pool.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>

#include "error.hpp"
#include "run/stop.hpp"

namespace cairn::bench {

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

void run_pool(const std::vector<PoolJob>& jobs, const PoolOptions& options,
              const std::function<std::unique_ptr<Backend>(const std::string&)>& make,
              const std::function<void(size_t, const PoolResult&, std::mutex&)>& done) {
    std::atomic<size_t> next{0};
    std::mutex lock, ode;
    size_t finished = 0;
    auto one = [&](const PoolJob& job, PoolResult& r) {
        std::vector<double> walls;
        for (int k = 0; k < std::max(1, options.repeats); ++k) {
            auto backend = make(job.backend);
            RunOptions ro;
            ro.contact_mode = job.contact_mode;
            RunResult res = run_scene(*backend, *job.scene, ro);
            walls.push_back(res.wall_seconds);
            if (k == 0) {
                r.outcome = res.status == RunStatus::completed     ? "completed"
                            : res.status == RunStatus::interrupted ? "interrupted"
                                                                   : "unstable";
                r.message = res.message;
                r.result = std::move(res);
                if (r.outcome != "completed") break;   // a blow-up's wall time means nothing
            }
        }
        r.median_wall = median(walls);
    };
    auto worker = [&] {
        for (size_t j; !stop_requested() && (j = next++) < jobs.size();) {
            const PoolJob& job = jobs[j];
            PoolResult r;
            try {
                if (job.backend == "ode") {
                    std::lock_guard<std::mutex> g(ode);
                    one(job, r);
                } else {
                    one(job, r);
                }
            } catch (const Error& e) {
                r.outcome = "refused";
                r.message = e.what();
            } catch (const std::exception& e) {
                r.outcome = "failed";
                r.message = std::string("unexpected failure: ") + e.what();
            }
            done(j, r, lock);
            std::lock_guard<std::mutex> g(lock);
            ++finished;
            if (!options.quiet)
                std::fprintf(stderr, "%s [%zu/%zu] %s %s: %s, %.3g s\n", options.tag.c_str(), finished, jobs.size(),
                             job.backend.c_str(), job.label.c_str(), r.outcome.c_str(), r.median_wall);
        }
    };
    const int n = std::max(1, std::min<int>(options.jobs, int(jobs.size())));
    std::vector<std::thread> pool;
    for (int i = 0; i < n; ++i) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
}

}  // namespace cairn::bench
