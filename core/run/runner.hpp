#pragma once
/// Drives a backend through a scene: steps, samples at the output interval, and stops a run that
/// goes unstable (NaN, or energy growing without a source) with a message naming the time and the
/// critical step.

#include <functional>
#include <string>
#include <vector>

#include "backend/backend.hpp"

namespace cairn {

enum class RunStatus { completed, unstable };

/// Everything a run produced.
struct RunResult {
    RunStatus status = RunStatus::completed;
    std::string message;             ///< why it stopped early (empty when completed)
    std::vector<Sample> samples;     ///< t = 0 first, one per output interval
    double dt = 0.0;                 ///< s
    double critical_step = 0.0;      ///< s, as the backend estimated it (0 = unknown)
    long long steps = 0;             ///< steps taken
    int output_every = 1;            ///< steps between samples
    double wall_seconds = 0.0;       ///< wall time of the stepping loop, s
    bool energy_drift = false;       ///< balance error exceeded the drift bound at some sample
    double max_balance_error = 0.0;  ///< largest |balance error| relative to the energy scale
};

/// called now and then with the fraction done, for a progress line on a terminal
using ProgressFn = std::function<void(double fraction)>;

/// build `backend` from `scene` and run it for scene.run.duration
RunResult run_scene(Backend& backend, const Scene& scene, const RunOptions& options,
                    const ProgressFn& progress = {});

}  // namespace cairn
