#pragma once
/// The overturning study (docs/studies.md): a rigid block on its base under pulses of ground
/// acceleration over a grid of amplitude a_p/(g tan α) × frequency ω_p/p, each point run on every
/// backend and on the rocking oracle; the minimum overturning amplitude per frequency by bisection.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "analytic/rocking_oracle_pulse.hpp"
#include "backend/backend.hpp"
#include "scene/scene_io.hpp"

namespace cairn::study {

/// What to study.
struct OverturningSetup {
    std::string scene_text;            ///< TOML of the block on its fixed base, without [ground_motion]
    std::string scene_source;          ///< names it in messages (a path, or "--block")
    std::vector<Override> overrides;   ///< applied to every backend scene (--set)
    double b = 0.0, h = 0.0;           ///< the block's half-width along x and half-height, m
    double g = 9.81;                   ///< m/s²
    oracle::PulseShape pulse = oracle::PulseShape::sine;
    std::vector<double> levels;        ///< grid amplitudes a_p / (g tan α), ascending
    std::vector<double> ratios;        ///< grid frequencies ω_p / p, ascending
    int bisect = 10;                   ///< bisection steps of each minimum overturning amplitude
    std::vector<std::string> backends; ///< registry names
    int jobs = 2;                      ///< runs at a time
    /// backends whose runs must not overlap (not thread-safe), by name; empty = none
    std::function<bool(const std::string&)> exclusive;
    bool quiet = false;                ///< no progress lines
    double tail = 5.0;                 ///< s simulated after the pulse at most (runs stop once decided)
};

/// The one free block of a scene as the oracle sees it.
struct RockingBlockOf {
    int block = -1;          ///< index into Scene::blocks
    double b = 0.0, h = 0.0; ///< half-width along x and half-height, m
    double g = 9.81;         ///< |gravity|, m/s² (along −z)
};
/// the scene's only free block, upright, with gravity along −z; throws cairn::Error naming the key otherwise
RockingBlockOf rocking_block_of(const Scene& scene);

/// the block of `W × D × H` m (x, y, z) on a fixed 0.5 m slab, as TOML (stone, friction 5 so that the
/// block rocks and never slides). The in-house engine's contact is set to rock like Housner's block:
/// hitting points only on the two bottom edges across the rocking axis (grid spacing W), kn = ks =
/// 3e10 N/m³, ζ = 0.6 (docs/studies.md, "The in-house engine's contact"); the other engines' own
/// contacts ignore these keys
std::string block_scene_text(double width, double depth, double height);

/// the setup's default grid: 8 amplitudes and 9 frequencies ω_p/p = 1…9
std::vector<double> default_levels();
std::vector<double> default_ratios();

/// the oracle of the setup's block
oracle::RockingOracle setup_oracle(const OverturningSetup& s);
/// the pulse of a grid point
oracle::Pulse point_pulse(const OverturningSetup& s, double ratio, double level);
/// the backend scene of a pulse: the template with the pulse as an inline [ground_motion] and the
/// duration cut to the pulse plus the tail; throws cairn::Error if the template has its own motion
Scene pulse_scene(const OverturningSetup& s, const oracle::Pulse& pulse);

/// a scene from TOML text with `accel` (m/s² along +x) as an inline [ground_motion], the overrides
/// and the duration (s) applied
Scene motion_scene(const std::string& text, const std::string& source, std::vector<Override> overrides,
                   const TimeSeries& accel, double duration);

/// One run of a pulse on a method (a backend, or "oracle").
struct OverturningRun {
    std::string method;
    double ratio = 0.0, level = 0.0;   ///< ω_p/p, a_p/(g tan α)
    bool overturned = false;
    double max_theta = 0.0;            ///< largest |θ| seen, rad
    std::string status = "completed";  ///< or why the run failed (then `overturned` is meaningless)
    double wall_seconds = 0.0;
};

/// how a backend run's samples decide it: |θ| ≥ π/3 is overturned (past α it falls, and no pulse
/// brings it back from there); after the pulse, a block whose energy above rest is below half the
/// hill m g R (1 − cos α) can no longer overturn; at the end of the run, |θ| > α counts as overturned
struct VerdictRule {
    double pulse_end = 0.0;   ///< s
    double hill = 0.0;        ///< J
    double alpha = 0.0;       ///< rad
};

/// call fn(i) for i in [0, n) on the run layer's pool (run_on_cores, at most `jobs` at a time), the
/// calls of a backend for which exclusive(name) is true (not thread-safe) one at a time;
/// `method(i)` names job i's backend; no new call starts once a stop is requested
void run_pool(size_t n, int jobs, const std::function<std::string(size_t)>& method,
              const std::function<void(size_t)>& fn, const std::function<bool(const std::string&)>& exclusive);

/// run every job (backend, ratio, level) on the pool (runs of a backend that is not thread-safe one at a time);
/// deterministic: results are in job order whatever the thread count
using BackendMaker = std::function<std::unique_ptr<Backend>(const std::string&)>;
std::vector<OverturningRun> run_overturning_jobs(const OverturningSetup& s, const std::vector<OverturningRun>& jobs,
                                                 const BackendMaker& make);

/// the oracle's verdict of one point
OverturningRun oracle_run(const OverturningSetup& s, double ratio, double level);

/// The minimum overturning amplitude of a method at one frequency.
struct Boundary {
    std::string method;
    double ratio = 0.0;
    double lo = NAN, hi = NAN;   ///< the last safe and first overturning amplitude, a_p/(g tan α)
    double level() const { return 0.5 * (lo + hi); }
    bool found() const { return std::isfinite(lo) && std::isfinite(hi); }
    std::string note;            ///< why not found ("no overturning on the grid", a failed run)
    std::vector<double> flips;   ///< oracle: every verdict change within 0.8-1.2 of its minimum
};

/// The whole study.
struct OverturningResult {
    std::vector<OverturningRun> grid;         ///< every method × ratio × level
    std::vector<OverturningRun> bisection;    ///< the bisection runs of the backends
    std::vector<Boundary> boundaries;         ///< every method × ratio
    std::vector<double> fine_ratios;          ///< the oracle's boundary on a fine frequency grid
    std::vector<double> fine_levels;          ///< a_p/(g tan α) (NaN: none found below the top)
    std::vector<std::string> non_monotonic;   ///< notes on the oracle's verdicts flipping more than once
    double wall_seconds = 0.0;
};

/// the grid jobs of the backends (method × ratio × level, in that order): the one place where the
/// study's runs are listed, for any job runner
std::vector<OverturningRun> grid_jobs(const OverturningSetup& s);

/// run the study
OverturningResult run_overturning(const OverturningSetup& s, const BackendMaker& make);

/// write DIR/overturning.csv, DIR/overturning_boundary.csv, figures, DIR/overturning.md and .html
void write_overturning_study(const std::string& dir, const OverturningSetup& s, const OverturningResult& r);

}  // namespace cairn::study
