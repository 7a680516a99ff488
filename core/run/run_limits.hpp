#pragma once
/// Limits that refuse an absurd run before any work (docs/cli.md, docs/scenes.md "Limits"):
/// the step and row counts, a fixed time step above the critical step, the memory of the model.

#include <string>

namespace cairn {

class Backend;
struct Scene;

/// most steps of a run without allow_large
constexpr double kMaxSteps = 1e9;
/// most trajectory rows of a run without allow_large
constexpr double kMaxRows = 1e8;

/// What a run may cost; part of RunOptions.
struct RunLimits {
    bool allow_large = false;        ///< accept more than kMaxSteps steps or kMaxRows rows
    bool allow_unstable_dt = false;  ///< accept a given run.dt above the backend's critical step
    double memory_budget = 0.0;      ///< bytes the model may take; 0 = half of the machine's RAM
};

/// The size of a run: steps, and the sampling that follows from them.
struct RunSize {
    long long steps = 0;          ///< ceil(duration / dt)
    long long output_every = 1;   ///< steps between samples (at most `steps`)
    long long rows = 0;           ///< samples: t = 0, every output_every steps, the last step
};

/// the size of `scene`'s run at time step dt (s); throws cairn::Error naming the keys and values
/// when dt is not positive and finite, or when the steps or rows pass the limits (unless
/// allow_large), or when a given run.dt exceeds critical (s, 0 = unknown) (unless
/// allow_unstable_dt). Everything is computed in double before any conversion.
RunSize check_run_size(const Scene& scene, const std::string& backend, double dt, double critical,
                       const RunLimits& limits);

/// the memory budget in bytes: limits.memory_budget, or half of the machine's physical memory
double memory_budget(const RunLimits& limits);

/// physical memory of the machine, bytes (sysconf, else /proc/meminfo; 0 if unknown)
double machine_memory();

/// "1.5 GiB", "300 MiB", "12 KiB", "100 B"
std::string bytes_text(double bytes);

}  // namespace cairn
