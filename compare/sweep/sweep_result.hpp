#pragma once
/// The result of one sweep run: read from the run's directory (trajectory and status), kept as a
/// small JSON file per run (DIR/results/<id>.json), read back for the merge.

#include <string>

#include "sweep/sweep_runs.hpp"

namespace cairn::sweep {

/// What one run gave.
struct SweepResult {
    std::string id;                     ///< the run's id
    std::string status = "error";       ///< "completed", "unstable", "interrupted", "error", "refused"
    std::string message;                ///< why not completed
    bool overturned = false;            ///< final tilt of the block > its overturning angle
    double peak_rotation = 0.0;         ///< largest tilt of the block's z axis from the vertical, rad
    double final_rotation = 0.0;        ///< tilt at the last sample, rad
    double residual_displacement = 0.0; ///< horizontal distance of the centre of mass from its start at the end, m
    double duration = 0.0;              ///< simulated time of the last sample, s
    long long steps = 0;                ///< steps taken
    double dt = 0.0;                    ///< time step, s
    double wall_seconds = 0.0;          ///< s (varies between runs: kept out of the merged table)
};

/// the tilt, peak and final rotation and residual displacement of `block` from the trajectory in
/// `run_dir` (trajectory.csv, else trajectory.partial.csv); fills those fields of `r`; throws
/// cairn::Error naming the file when it cannot be read
void read_trajectory_outcome(const std::string& run_dir, const SweepRun& run, SweepResult& r);

/// the JSON text of a result
std::string result_json(const SweepRun& run, const SweepResult& r);

/// read a result file; throws cairn::Error naming the file when it is not one
SweepResult read_result(const std::string& path);

}  // namespace cairn::sweep
