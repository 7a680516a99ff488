// The core pool: workers × OpenMP threads never exceed the cores, every task runs once, exclusive
// tasks never overlap, a task's exception reaches the caller
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "run/core_pool.hpp"

using namespace cairn;

TEST_CASE("the core share never puts more threads than cores", "[run][pool]") {
    const int cores = machine_cores();
    REQUIRE(cores >= 1);
    for (size_t tasks : {size_t(0), size_t(1), size_t(2), size_t(7), size_t(100)})
        for (int jobs : {0, 1, 2, 3, 64}) {
            const CoreShare s = share_cores(tasks, jobs);
            CHECK(s.workers >= 1);
            CHECK(s.threads >= 1);
            CHECK(s.workers * s.threads <= cores);
            if (jobs > 0) CHECK(s.workers <= jobs);
        }
    // one job: the whole machine for its OpenMP team; one job per core: no team at all
    CHECK(share_cores(1, 0).threads == cores);
    CHECK(share_cores(100, 0).workers == cores);
    CHECK(share_cores(100, 0).threads == 1);
}

TEST_CASE("each worker's OpenMP regions use the share's threads", "[run][pool]") {
    for (int jobs : {1, 2}) {
        const CoreShare s = share_cores(8, jobs);
        std::mutex m;
        std::vector<int> seen;
        run_on_cores(8, jobs, [&](size_t) {
            std::lock_guard<std::mutex> lock(m);
            seen.push_back(openmp_threads());
        });
        REQUIRE(seen.size() == 8);
        for (int t : seen) CHECK((t == s.threads || t == 0));   // 0: built without OpenMP
        CHECK(seen.front() == seen.back());
    }
}

TEST_CASE("every task runs once and exclusive tasks never overlap", "[run][pool]") {
    constexpr size_t n = 40;
    std::vector<std::atomic<int>> runs(n);
    std::atomic<int> exclusive_now{0}, exclusive_max{0};
    run_on_cores(
        n, 0,
        [&](size_t i) {
            ++runs[i];
            if (i % 2 == 0) {
                const int k = ++exclusive_now;
                int m = exclusive_max.load();
                while (k > m && !exclusive_max.compare_exchange_weak(m, k)) {}
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
                --exclusive_now;
            }
        },
        [](size_t i) { return i % 2 == 0; });
    for (auto& r : runs) CHECK(r.load() == 1);
    CHECK(exclusive_max.load() == 1);
}

TEST_CASE("a task's exception ends that task only and is rethrown after the others", "[run][pool]") {
    std::atomic<int> ran{0};
    CHECK_THROWS_AS(run_on_cores(6, 2,
                                 [&](size_t i) {
                                     ++ran;
                                     if (i == 1) throw std::runtime_error("task 1");
                                 }),
                    std::runtime_error);
    CHECK(ran.load() == 6);
}
