#pragma once
/// The subcommands of the cairn executable; each returns the process exit code.

#include <string>
#include <vector>

#include "run_job.hpp"

namespace cairn {

/// exit codes of the cairn executable
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;     ///< an unexpected failure (a bug, a write error)
constexpr int kExitBadInput = 2;    ///< bad scene, option, backend or output dir; nothing written
constexpr int kExitUnstable = 3;    ///< the run went unstable; partial outputs written

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

/// true when stderr is a terminal (progress lines make sense)
bool stderr_is_terminal();

}  // namespace cairn
