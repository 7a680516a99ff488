#pragma once
/// Running an external program without a shell: an argument vector handed to posix_spawn, the
/// working directory set in the child, output to a file. Nothing in the arguments is interpreted.

#include <string>
#include <vector>

namespace cairn::report {

/// the full path of the executable `name` found on $PATH (as execvp would), or "" when none
std::string find_on_path(const std::string& name);

/// run `argv` (argv[0] a path to the executable) in directory `dir` ("" = ours), stdin from
/// /dev/null, stdout and stderr into `log` (relative to `dir`; "" = /dev/null); waits for it.
/// Returns its exit status, or -1 when it could not start or was killed by a signal.
int run_program(const std::vector<std::string>& argv, const std::string& dir, const std::string& log);

}  // namespace cairn::report
