#pragma once
/// Running every case × variant of a validation on a pool of threads, each run isolated: a run the
/// backend refuses or that throws is recorded as such and never stops the others.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "cases/case_analysis.hpp"
#include "validation/plan.hpp"

namespace cairn::validation {

/// makes a backend by registry name (the app passes make_backend; compare never sees engines)
using BackendFactory = std::function<std::unique_ptr<Backend>(const std::string&)>;

/// How one run ended.
enum class Outcome { completed, unstable, refused, failed };

/// "completed", "unstable", "cannot represent", "failed"
const char* to_string(Outcome o);

/// One case × variant.
struct CaseRun {
    std::string case_name;
    Variant variant;
    Outcome outcome = Outcome::failed;
    std::string message;              ///< why it was refused, failed or went unstable
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
    int jobs = 2;                    ///< threads
    /// backends whose runs must not overlap (a library with global state, e.g. ODE built without
    /// per-thread collision data)
    std::vector<std::string> serial_backends;
    bool quiet = false;              ///< no progress lines on stderr
};

/// run every listed run of the plan, then analyse each against its case and diff the variants;
/// fills the CaseRun entries in place; once a stop is requested (run/stop.hpp) no new run starts
void run_plan(RunPlan& plan, const BackendFactory& make);

}  // namespace cairn::validation
