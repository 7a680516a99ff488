#pragma once
/// One run of one scene on one backend into an output directory: the work behind `cairn run`,
/// shared by `cairn run-all`.

#include <string>
#include <vector>

#include "run/run_jobs.hpp"
#include "run/run_limits.hpp"

namespace cairn {

/// What to run and where.
struct RunJob {
    std::string scene;                    ///< scene file path or shipped scene name
    std::string backend;                  ///< registry name
    std::string out_dir;                  ///< output directory
    bool force = false;                   ///< replace a non-empty directory (its old content goes)
    std::vector<std::string> overrides;   ///< "key=value" scene overrides
    std::string model;                    ///< "rigid"/"deformable" for every free block; empty = scene's
    std::string contact = "rigid";        ///< contact mode of the reference engines
    bool progress = false;                ///< show a progress line on stderr
    std::string label;                    ///< name shown in the progress line
    RunLimits limits;                     ///< --allow-large, --allow-unstable-dt, --memory-budget
    bool vtk = false;                     ///< write the VTK series for ParaView into out_dir/vtk/
    bool replay = false;                  ///< write the 3-D replay page out_dir/replay.html
    bool contacts = false;                ///< write every sample's contact points to out_dir/contacts.csv
};

/// How a run ended: the run layer's one vocabulary (input_error: bad scene, override, backend name
/// or output dir, nothing written; refused: the backend cannot build this scene, nothing written)
using JobStatus = Outcome;

/// What a run produced, for the summary line and the run-all table.
struct JobOutcome {
    JobStatus status = JobStatus::input_error;
    std::string message;              ///< error or instability message
    long long steps = 0;              ///< steps taken
    double dt = 0.0;                  ///< s
    double wall_seconds = 0.0;        ///< s
    double final_balance_error = 0.0; ///< J, last sample's total energy minus the first's
    bool energy_drift = false;        ///< the balance error passed the drift bound
    double max_balance_error = 0.0;   ///< largest balance error relative to the energy scale
    std::string energy_created;       ///< energy_created_text of the run: empty unless energy appeared from nowhere
    std::vector<std::string> warnings;///< the backend's warnings about this run ("warning: ..."), for stderr
};

/// run `job`: the outputs appear in job.out_dir as a set (output/staged_dir.hpp) or not at all;
/// cairn::Error from input or the backend becomes input_error/refused, other exceptions (a write
/// error) propagate and leave job.out_dir as it was
JobOutcome execute_run(const RunJob& job);

/// one-line summary of an outcome: steps, dt, wall time, final balance error
std::string summary_line(const JobOutcome& o);

}  // namespace cairn
