#pragma once
/// The subcommands of the cairn executable; each returns the process exit code.

#include <map>
#include <string>
#include <vector>

#include "run_job.hpp"

namespace CLI {
class App;
}

namespace cairn {

/// exit codes of the cairn executable
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;     ///< an unexpected failure (a bug, a write error)
constexpr int kExitBadInput = 2;    ///< bad scene, option, backend or output dir; nothing written
constexpr int kExitUnstable = 3;    ///< the run went unstable; partial outputs written
constexpr int kExitInterrupted = 130;   ///< stopped by SIGINT/SIGTERM (128 + SIGINT, as shells do)

/// `cairn run`: one scene on one backend
int run_command(RunJob job, bool quiet);

/// `cairn list`: the shipped scenes and the backends with their capabilities
int list_command();

/// Options of `cairn run-all`.
struct RunAllOptions {
    std::string out_dir = "out";          ///< outputs go to out_dir/<scene>/<backend>/
    std::vector<std::string> backends;    ///< empty = every available backend
    bool quiet = false;                   ///< no progress lines
};

/// `cairn run-all`: every shipped scene on every backend, then a summary table
int run_all_command(const RunAllOptions& options);

/// Options of `cairn study inertia`.
struct StudyInertiaOptions {
    std::string out_dir = "out/study";   ///< inertia.csv, inertia.md, inertia.html, figures/
    int repeats = 3;                     ///< runs per point; the wall time is their median
    int jobs = 2;                        ///< runs at a time
    std::vector<int> ns;                 ///< elements per side; empty = 1, 2, 4, 8
    bool quiet = false;                  ///< no progress lines
};

/// `cairn study inertia`: every mass scheme x mesh on the rocking and impact scenes (docs/inertia.md)
int study_inertia_command(const StudyInertiaOptions& options);

/// Options of `cairn study contact`.
struct StudyContactOptions {
    std::string out_dir = "out/contact";   ///< contact.csv, contact.md, contact.html, figures/
    std::vector<double> kns;               ///< N/m³; empty = 3e7, 3e8, 3e9
    std::vector<double> spacings;          ///< paper grid spacings, m; empty = 0.2, 0.1, 0.05, 0.025
    std::vector<int> subdivisions;         ///< overlap sub-divisions; empty = 1, 2, 4, 8
    int repeats = 3;                       ///< runs per point; the wall time is their median
    int jobs = 2;                          ///< runs at a time
    bool quiet = false;                    ///< no progress lines
};

/// `cairn study contact`: the paper's grid against the overlap integral on the rocking block
/// (docs/studies.md)
int study_contact_command(const StudyContactOptions& options);

/// Options of `cairn study overturning` (docs/cli.md).
struct StudyOverturningOptions {
    std::string scene;                    ///< a scene with one free block on a fixed base, or empty
    std::vector<double> block;            ///< --block W,H[,D]: the block's width, height, depth, m
    std::string pulse = "sine";           ///< sine, cosine, ricker
    std::vector<std::string> backends;    ///< empty or "all" = every available backend
    std::string grid = "8x9";             ///< amplitudes x frequencies
    std::vector<double> levels;           ///< --levels: the grid's a_p/(g tan a) instead of --grid's
    std::vector<double> ratios;           ///< --ratios: the grid's w_p/p instead of --grid's
    int bisect = 10;                      ///< bisection steps per minimum overturning amplitude
    int jobs = 2;                         ///< runs at a time
    std::vector<std::string> overrides;   ///< --set key=value for every backend scene
    std::string out_dir = "out/overturning";
    bool quiet = false;
};

/// `cairn study overturning`: overturning spectra of every backend against the rocking oracle
int study_overturning_command(const StudyOverturningOptions& options);
/// Options of `cairn study record` (docs/cli.md).
struct StudyRecordOptions {
    std::string scene;                    ///< a scene with one free block and a [ground_motion], or empty
    std::vector<double> block;            ///< --block W,H[,D], m
    std::string record;                   ///< --record CSV (t_s, accel_g) for --block; default El Centro
    double duration = 10.0;               ///< s, with --block
    std::vector<std::string> backends;    ///< empty or "all" = every available backend
    int jobs = 2;
    std::vector<std::string> overrides;   ///< --set key=value
    std::string out_dir = "out/record";
    bool quiet = false;
};

/// `cairn study record`: each backend's rocking under a record against the rocking oracle
int study_record_command(const StudyRecordOptions& options);
/// declare `study record` and its options under `study`
CLI::App* add_study_record(CLI::App& study, StudyRecordOptions& options);
/// declare `study overturning` and its options under `study`
CLI::App* add_study_overturning(CLI::App& study, StudyOverturningOptions& options);
/// the `study contact` subcommand and its options
CLI::App* add_study_contact(CLI::App& study, StudyContactOptions& options);

/// Options of `cairn validate`.
struct ValidateOptions {
    std::string out_dir = "out/validation";   ///< summary.csv, report.md, index.html, runs/, figures/
    std::vector<std::string> backends;        ///< empty = every available backend
    std::vector<std::string> cases;           ///< empty = every paper case
    std::vector<std::string> overrides;       ///< "key=value" applied to every run's scene
    int jobs = 2;                             ///< runs at a time
    bool quiet = false;                       ///< no progress lines
    std::string study_dir;                    ///< inertia study to include (default: DIR/study if present)
    std::string contact_dir;                  ///< contact study to include (default: DIR/contact if present)
    std::string bench_dir;                    ///< bench results to include (default: DIR/bench if present)
};

/// `cairn validate`: the paper's cases on every backend against their analytic references
int validate_command(const ValidateOptions& options);

/// Options of `cairn compare`.
struct CompareOptions {
    std::string scene;                        ///< scene file or shipped scene name
    std::vector<std::string> backends;        ///< empty or "all" = every available backend
    std::string model = "both";               ///< block models of dem: "rigid", "deformable" or "both"
    std::string out_dir;                      ///< report dir; empty = out/compare/<scene file stem>
    std::string baseline;                     ///< variant the others are compared with; empty = dem-rigid
    std::vector<std::string> overrides;       ///< "key=value" applied to the scene
    int jobs = 0;                             ///< runs at a time; 0 = the machine's cores
    bool quiet = false;                       ///< no progress lines
};

/// `cairn compare`: one scene on every backend variant that takes it, and the comparison report
int compare_command(const CompareOptions& options);

/// Options of `cairn bench` (docs/bench.md).
struct BenchOptions {
    std::string out_dir = "out/bench";   ///< trade.csv, stability.csv, wall.csv, bench.md, bench.html, figures/
    std::vector<std::string> backends;   ///< empty = every available backend
    std::vector<std::string> cases;      ///< trade: rocking, rocking_slender, impact (empty = all)
    bool full = false;                   ///< trade: the big sweep
    bool quick = false;                  ///< trade: two or three points per backend (tests)
    int repeats = 3;                     ///< runs per trade point / wall backend; wall time is their median
    int jobs = 2;                        ///< points at a time
    long long long_steps = 1000000;      ///< stability: steps of the long resting run
    int courses = 30;                    ///< wall: courses of 10 bricks
    int wall_steps = 200;                ///< wall: steps per repeat
    std::vector<int> scale_sizes{1000, 3000, 10000};   ///< scale: bricks per wall, count
    int scale_steps = 5;                 ///< scale: steps timed per wall and backend
    bool pushover = true;                ///< scale: also the wall pushover accuracy measure (minutes)
    bool large = false;                  ///< scale: run only the building-scale model under El Centro on dem
    int large_blocks = 10000;            ///< scale --large: bricks of the tower, count
    double large_duration = 1.0;         ///< scale --large: simulated time from the record's start, s
    bool quiet = false;                  ///< no progress lines
};

/// `cairn bench trade|stability|wall|scale|all`
int bench_command(const std::string& which, const BenchOptions& options);

/// Options of `cairn replay`.
struct ReplayOptions {
    std::vector<std::string> run_dirs;   ///< directories written by `cairn run`, one view each
    std::string out = "replay.html";     ///< the page
    std::string title;                   ///< page title; empty = "cairn replay"
};

/// `cairn replay`: the 3-D replay page of several runs side by side
int replay_command(const ReplayOptions& options);

/// Options of `cairn make`.
struct MakeOptions {
    /// generator → parameter name → value as typed (a number with an optional unit, e.g. "40cm")
    std::map<std::string, std::map<std::string, std::string>> values;
    std::string out;   ///< scene file written atomically; empty = standard output
};

/// the scene text of generator `kind` (arch, wall, column, tower, house) for the parameter values
/// (missing ones take their defaults); throws cairn::Error naming a bad option and its value.
/// `warning`, if given, receives why the scene may not behave as its parameters suggest (an arch
/// whose joints are too soft to stand on dem), also written as a comment line; empty if none
std::string make_scene_text(const std::string& kind, const std::map<std::string, std::string>& values,
                            std::string* warning = nullptr);

/// add `cairn make` and its generators to `app`, binding their options to `options`; returns the
/// generators' subcommands
std::vector<CLI::App*> add_make_commands(CLI::App& app, MakeOptions& options);

/// `cairn make KIND`: write the generated scene (checked by the loader) to stdout or options.out
int make_command(const std::string& kind, const MakeOptions& options);

/// true when stderr is a terminal (progress lines make sense)
bool stderr_is_terminal();

/// say on stderr that a command was interrupted and `dir` keeps its previous `what`; returns
/// kExitInterrupted
int interrupted_keeping(const std::string& what, const std::string& dir);

}  // namespace cairn
