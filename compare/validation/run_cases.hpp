#pragma once
/// Running every case × variant of a validation on a pool of threads, each run isolated: a run the
/// backend refuses or that throws is recorded as such and never stops the others.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend_info.hpp"
#include "cases/case_analysis.hpp"
#include "run/run_jobs.hpp"
#include "validation/plan.hpp"

namespace cairn::validation {

/// a run's outcome in the reports: "completed", "unstable", "interrupted", "cannot represent"
/// (refused), "failed" (an input error or any other failure)
const char* outcome_text(Outcome o);

/// One case × variant.
struct CaseRun {
    std::string case_name;
    Variant variant;
    Outcome outcome = Outcome::failed;
    std::string message;              ///< why it was refused, failed or went unstable
    double energy_gain = 0.0;         ///< J, RunResult::energy_gain: energy that appeared without a source
    std::string energy_created;       ///< energy_created_text of the run (empty unless flagged)
    std::vector<std::string> warnings;///< the backend's warnings about the run ("warning: ...")
    std::vector<Sample> samples;      ///< what it produced (partial when unstable)
    double wall_seconds = 0.0;        ///< s, the stepping loop
    double dt = 0.0;                  ///< s
    long long steps = 0;
    bool analysed = false;            ///< `analysis` holds the case's metrics
    cases::CaseAnalysis analysis;
    std::vector<metrics::Metric> diffs;   ///< against the case's first completed variant
    std::string out_dir;              ///< where trajectory.csv and run.json went
};

/// One case with its scene and runs.
struct CaseResult {
    std::string name;
    Scene scene;
    std::vector<CaseRun> runs;
};

/// What to run.
struct RunPlan {
    std::vector<CaseResult> cases;   ///< scene loaded, runs listed (case_name and variant set)
    std::string out_dir;             ///< runs are written to out_dir/runs/<case>/<variant>/
    /// where out_dir is moved once the report is complete (a staging directory swapped into
    /// place); the runs are named by it in CaseRun::out_dir; empty = out_dir
    std::string final_dir;
    std::vector<std::string> overrides;   ///< "key=value" applied to every scene (recorded in run.json)
    std::vector<std::string> scene_paths; ///< per case, the scene file (for run.json)
    int jobs = 2;                    ///< runs at a time (at most the cores)
    bool quiet = false;              ///< no progress lines on stderr
    /// called from the pool threads with a run's index (cases and runs in plan order) and its
    /// fraction done, 1 once it ended; the callee serialises; empty = none
    std::function<void(size_t run, double fraction)> progress;
};

/// run every listed run of the plan on the run layer (run/run_jobs.hpp), then analyse each against
/// its case and diff the variants; fills the CaseRun entries in place; once a stop is requested
/// (run/stop.hpp) no new run starts
void run_plan(RunPlan& plan, const std::vector<BackendInfo>& backends);

}  // namespace cairn::validation
