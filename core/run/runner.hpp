#pragma once
/// Drives a backend through a scene: steps, hands a sample to a sink at every output interval, and
/// stops a run that goes unstable (NaN, or energy growing without a source) with a message naming
/// the time and the critical step, or that is asked to stop (run/stop.hpp). The energy checks keep
/// running summaries, so a run's memory does not grow with its length.

#include <functional>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "run/sample_sink.hpp"

namespace cairn {

/// a balance error beyond this fraction of the motion's energy (EnergyBounds::motion) sets
/// RunResult::energy_drift (the run goes on): 1 %
constexpr double kDriftBound = 0.01;

/// energy appearing without a source: a rise of the balance error above its lowest value so far by
/// more than this fraction of EnergyBounds::created (the motion's energy, at least the heaviest
/// free block's m·g·diameter) sets RunResult::energy_created (the run goes on): 10 %. Measured
/// from the lowest value, a gain shows even after losses a backend does not book (the rigid
/// engines' impacts), which would otherwise hide it in the balance error
constexpr double kCreatedBound = 0.1;

/// How a run ended: every step taken, stopped because it went unstable, or stopped on request.
enum class RunStatus { completed, unstable, interrupted };

/// Everything a run produced.
struct RunResult {
    RunStatus status = RunStatus::completed;
    std::string message;             ///< why it stopped early (empty when completed)
    std::vector<Sample> samples;     ///< t = 0 first, one per output interval; filled only by the
                                     ///< run_scene overload without a sink
    long long sample_count = 0;      ///< samples handed to the sink
    double initial_total = 0.0;      ///< total energy of the first sample, J
    double final_time = 0.0;         ///< time of the last sample, s
    Energies final_energy;           ///< energies of the last sample, J
    double dt = 0.0;                 ///< s
    double critical_step = 0.0;      ///< s, as the backend estimated it (0 = unknown)
    long long steps = 0;             ///< steps taken
    int output_every = 1;            ///< steps between samples
    double wall_seconds = 0.0;       ///< wall time of the stepping loop, s
    bool energy_drift = false;       ///< balance error exceeded kDriftBound at some sample
    double max_balance_error = 0.0;  ///< largest |balance error| relative to the energy scale
    double energy_gain = 0.0;        ///< J, the largest rise of the balance error above its lowest
                                     ///< value at an earlier sample: energy that appeared from nowhere
    double energy_gain_time = 0.0;   ///< s, the sample at which that rise was reached
    double energy_gain_scale = 0.0;  ///< J, the scale (EnergyBounds::created) that rise was judged against
    bool energy_created = false;     ///< the rise passed kCreatedBound of EnergyBounds::created
    std::vector<std::string> warnings;  ///< the backend's notes that begin "warning: ", at the end of the run
};

/// "energy appeared from nowhere: +130 J by t = 2.205 s (0.65 × its scale, …: 200 J)" when
/// the run set energy_created, else empty
std::string energy_created_text(const RunResult& r);

/// called now and then with the fraction done, for a progress line on a terminal
using ProgressFn = std::function<void(double fraction)>;

/// build `backend` from `scene` and run it for scene.run.duration, handing every sample to `sink`
/// as it is taken (begin, sample..., end); a sink's exception ends the run and propagates
RunResult run_scene(Backend& backend, const Scene& scene, const RunOptions& options, SampleSink& sink,
                    const ProgressFn& progress = {});

/// the same, with the samples collected into RunResult::samples
RunResult run_scene(Backend& backend, const Scene& scene, const RunOptions& options,
                    const ProgressFn& progress = {});

}  // namespace cairn
