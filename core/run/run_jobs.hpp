#pragma once
/// The run layer: a list of run jobs (scene, backend, options, repeats) executed on the core pool
/// (run/core_pool.hpp), each isolated — a run the backend refuses or that throws is a result, never
/// an exception that stops the others. Commands build job lists and read the results.

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "backend/backend_info.hpp"
#include "output/run_record.hpp"
#include "run/resume_log.hpp"
#include "run/runner.hpp"

namespace cairn {

/// How a job ended: one vocabulary for every command.
enum class Outcome {
    completed,     ///< every step taken
    unstable,      ///< stopped as unstable (partial outputs)
    interrupted,   ///< stopped by SIGINT/SIGTERM (partial outputs)
    refused,       ///< the backend cannot build the scene (cairn::Error): nothing written
    input_error,   ///< bad scene, override, backend name or output directory: nothing written
    failed,        ///< any other failure (a write error, an unexpected exception)
};

/// "completed", "unstable", "interrupted", "refused", "error", "failed"
const char* to_string(Outcome o);

/// the outcome of a run that ran
Outcome outcome_of(RunStatus s);

/// One run to make.
struct RunSpec {
    const Scene* scene = nullptr;   ///< ready to run (not owned)
    std::string backend;            ///< registry name
    RunOptions options;             ///< contact mode, limits
    int repeats = 1;                ///< runs for the median wall time (a run that did not complete: one)
    /// trajectory.csv and run.json are written here (output/run_files.hpp); empty = no files
    std::string out_dir;
    RunRequest request;             ///< what run.json records beyond the scene (scene path, overrides)
    bool keep_samples = true;       ///< RunResult::samples of the first run
    std::string label;              ///< the job in progress lines
};

/// What a job gave.
struct JobResult {
    Outcome outcome = Outcome::failed;
    std::string message;        ///< why it did not complete
    RunResult result;           ///< of the first run (runs are deterministic)
    double median_wall = NAN;   ///< median wall time of the repeats, s
    bool resumed = false;       ///< not run: kept by an earlier invocation (result and wall time empty)
    /// the caller's text of the result (one line): set by `done` to be kept in the resume log,
    /// or the kept text when resumed
    std::string record;
};

/// Options of a job list.
struct JobsOptions {
    int jobs = 0;   ///< jobs at a time (0 = one per core); never more than the cores
    /// s: a first run this long or longer is not repeated (its time is steady enough)
    double repeat_below = std::numeric_limits<double>::infinity();
    bool quiet = false;   ///< no "[k/n] tag backend label: outcome, t s" line per job on stderr
    std::string tag;      ///< the lines' prefix
    /// called from the workers with a job's index and fraction done (1 once ended); the callee
    /// serialises; empty = none
    std::function<void(std::size_t job, double fraction)> progress;
    /// resume: a job whose key (job_key) is in the log is not run, and a job that ends completed,
    /// unstable or refused is kept there with the record `done` gave it; nullptr = run every job
    ResumeLog* resume = nullptr;
};

/// a job's identity for resuming: text_hash of its scene (every parameter, as run.json records
/// it), backend name and options
std::string job_key(const RunSpec& job);

/// median of the values (NaN when empty)
double median(std::vector<double> v);

/// run every job on the backends of `backends` (jobs on a backend that is not thread-safe never
/// overlap); done(i, result) is called from a worker as job i ends (callers lock shared state).
/// Once a stop is requested no new job starts. With a resume log, the jobs it holds are handed to
/// done (resumed, their outcome and record as kept) first, in order, and are not run. Returns the
/// number of jobs run.
std::size_t run_jobs(const std::vector<RunSpec>& jobs, const std::vector<BackendInfo>& backends,
              const JobsOptions& options, const std::function<void(std::size_t, JobResult&)>& done);

}  // namespace cairn
