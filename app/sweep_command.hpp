#pragma once
/// `cairn sweep`: a plan of independent runs, run locally or as a Slurm job array, merged into one
/// table (docs/sweeps.md).

#include <string>
#include <vector>

namespace cairn {

/// Options of `cairn sweep` and `cairn sweep merge`.
struct SweepOptions {
    std::string plan;                  ///< the plan file (TOML)
    std::string out_dir;               ///< output directory; "" = out/sweeps/<plan file stem>
    int jobs = 2;                      ///< runs at a time (local)
    std::string shard;                 ///< "I/N": run only shard I of N (0-based), no merge
    bool resume = false;               ///< skip runs whose result file exists
    bool force = false;                ///< start over: drop the results of another or this sweep in the directory
    std::string scheduler = "local";   ///< "local" or "slurm"
    int tasks = 0;                     ///< slurm: array tasks (shards); 0 = min(runs, 16)
    int task_jobs = 1;                 ///< slurm: runs at a time inside each task
    std::vector<std::string> sbatch_args;   ///< slurm: extra sbatch options, each one argument
    bool quiet = false;                ///< no progress lines
    std::string merge_dir;             ///< `cairn sweep merge DIR`
};

/// `cairn sweep PLAN`
int sweep_command(const SweepOptions& options);

/// `cairn sweep merge DIR`
int sweep_merge_command(const SweepOptions& options);

/// Where a Slurm submission went.
struct SlurmSubmission {
    std::string array_job;   ///< job id of the array
    std::string merge_job;   ///< job id of the merge job (afterok on the array)
};

/// write DIR/slurm/task.sh and merge.sh and submit them with sbatch (an argument vector, no
/// shell): an array of `tasks` tasks, each `cairn sweep PLAN --shard i/tasks --resume`, and the
/// merge job after them; throws cairn::Error when sbatch is missing or refuses
SlurmSubmission submit_slurm_sweep(const std::string& cairn_exe, const std::string& plan, const std::string& dir,
                                   int tasks, int task_jobs, const std::vector<std::string>& sbatch_args);

}  // namespace cairn
