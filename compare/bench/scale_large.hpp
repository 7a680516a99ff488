#pragma once
/// `cairn bench scale --large`: a building-scale model of about 10⁴ bricks (a four-wall tower of
/// `cairn make tower` bricks) under the shipped El Centro record on the in-house engine: the wall
/// time, the steps, the peak memory, and the time extrapolated to the whole record.

#include <string>

#include "backend/backend.hpp"
#include "scene/tower_builder.hpp"

namespace cairn::bench {

/// the simulated time the large run's cost is extrapolated to: 15 s of strong motion, s
constexpr double kLargeRecordSeconds = 15.0;

/// courses, length and width (brick lengths) of a tower of about n bricks: about √n courses of
/// about √n bricks, length + width = (per course + 2)/2 split evenly, each side at least 3
TowerSpec large_tower(int n);

/// the tower of about n bricks with the generator's defaults (`cairn make tower`: kn = ks = 1e9
/// N/m³, μ = 0.7, ζ = 0.1, density 2600 kg/m³), the overlap scheme with one sub-contact per hitting
/// face, dt auto, shaken by `record` (a copy of a scene's [ground_motion]) for `duration` s,
/// sampled every 0.05 s
Scene large_scene(int n, const GroundMotion& record, double duration);

/// One run of the large model.
struct LargeRun {
    int blocks = 0;                  ///< free bricks
    double duration = 0.0;           ///< simulated, s
    double dt = 0.0;                 ///< s
    double critical_step = 0.0;      ///< s
    long long steps = 0;             ///< steps taken
    double wall_seconds = 0.0;       ///< of the stepping loop, s
    double build_seconds = 0.0;      ///< building the model (blocks, critical step, first forces), s
    double peak_mb = 0.0;            ///< resident peak while building and running, MB
    double contacts = 0.0;           ///< active sub-contacts per step, mean over the samples after t = 0
    double max_balance_error = 0.0;  ///< largest |energy balance error| / the motion's energy scale
    bool energy_closed = false;      ///< the balance stayed within the runner's 1 % drift bound
    std::string status;              ///< "completed", "unstable: …", "interrupted"
    /// wall seconds per simulated second
    double cost() const { return duration > 0.0 ? wall_seconds / duration : 0.0; }
    /// ns of wall time per sub-contact and step
    double ns_per_contact() const { return steps > 0 && contacts > 0.0 ? 1e9 * wall_seconds / (steps * contacts) : 0.0; }
};

/// build `backend` on large_scene(n, record, duration) and run it, samples dropped
LargeRun run_large(Backend& backend, int n, const GroundMotion& record, double duration);

/// scale_large.csv text (one row, with the extrapolation to kLargeRecordSeconds) and its parse
std::string large_csv(const LargeRun& r);
LargeRun parse_large_csv(const std::string& text);

}  // namespace cairn::bench
