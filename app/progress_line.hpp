#pragma once
/// The progress line of a run on a terminal: simulated time, steps per second and the time left,
/// rewritten in place on stderr.

#include <chrono>
#include <mutex>
#include <string>
#include <vector>

#include "run/runner.hpp"

namespace cairn {

/// A sink that only notes the run's time step and start (hand it to run_scene beside the real
/// sink through a TeeSink) and draws the line when its progress function is called.
class ProgressLine : public SampleSink {
public:
    /// `label` starts the line; `duration` is the simulated time of the run, s
    ProgressLine(std::string label, double duration);
    void begin(const Scene& scene, const RunResult& run) override;
    void sample(const Sample&) override {}
    /// the function to pass to run_scene
    ProgressFn function();
    /// erase the line (after the run)
    void clear() const;

private:
    std::string label_;
    double duration_;
    double dt_ = 0.0;
    std::chrono::steady_clock::time_point start_;
    size_t width_ = 0;
};

/// The progress line of several runs of one scene on a pool of threads (cairn compare): runs
/// done, simulated time summed over the runs, time left. Safe to call from the pool threads.
class PoolProgress {
public:
    /// `runs` runs of `duration` simulated seconds each
    PoolProgress(std::string label, size_t runs, double duration);
    /// run `run` is `fraction` done (1 = ended); redraws the line
    void update(size_t run, double fraction);
    /// erase the line
    void clear();

private:
    std::mutex mutex_;
    std::string label_;
    double duration_;
    std::vector<double> done_;
    std::chrono::steady_clock::time_point start_;
    size_t width_ = 0;
};

/// the text of the line: "label: t = 1.23 / 5 s, 12 345 steps/s, 4 s left"
std::string progress_text(const std::string& label, double fraction, double duration, double dt, double elapsed);

}  // namespace cairn
