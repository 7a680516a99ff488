#pragma once
/// A sweep plan expanded into independent runs with stable ids, and the shards of a sweep.

#include <cstddef>
#include <string>
#include <vector>

#include "sweep/sweep_plan.hpp"

namespace cairn::sweep {

/// One run of a sweep.
struct SweepRun {
    std::size_t index = 0;        ///< position in the expansion (the merged table's row order)
    std::string id;               ///< 16 hex digits hashed from what the run is (not from where it is)
    std::string scene;            ///< scene file, absolute
    std::string scene_name;       ///< as written in the plan
    std::string backend;          ///< as in the plan: a registry name or a variant ("bullet-matched", backend_variant)
    std::string record;           ///< record name, or "scene" for the scene's own ground motion
    double intensity = 0.0;       ///< peak ground acceleration of the scaled record, g
    double scale = 1.0;           ///< ground_motion.scale that gives it
    std::vector<std::string> axis_values;   ///< one per plan axis, TOML text
    int repeat = 0;               ///< 0-based
    std::vector<std::string> overrides;     ///< every "key=value" of the run
    std::string block;            ///< the block whose outcome is recorded
    double overturn_angle = 0.0;  ///< rad: overturned when the final tilt exceeds it
};

/// The expanded sweep.
struct Sweep {
    SweepPlan plan;
    std::vector<SweepRun> runs;
};

/// expand `plan`; synthetic pulse records are written as CSV files into `records_dir` (created;
/// a file is rewritten only when its content differs). Every scene is loaded with its overrides
/// once here, so that a bad key or record fails before any run. Throws cairn::Error.
Sweep expand_sweep(const SweepPlan& plan, const std::string& records_dir);

/// the runs of shard `i` of `n`: every n-th run from the i-th (0 <= i < n)
std::vector<SweepRun> shard_of(const std::vector<SweepRun>& runs, int i, int n);

/// a canonical text of what the sweep is (ids and their meaning, no paths): two expansions with
/// the same manifest produce the same table
std::string sweep_manifest(const Sweep& sweep);

/// the CSV text of a synthetic pulse (t_s, accel_g) with unit peak
std::string pulse_csv(const RecordSpec& rec);

}  // namespace cairn::sweep
