#pragma once
/// The options that lift or set the limits of a run (docs/cli.md, "Limits").

#include <CLI/CLI.hpp>

#include "run/run_limits.hpp"

namespace cairn {

/// --allow-large, --allow-unstable-dt and --memory-budget on `cmd`, into `limits`
void add_limit_options(CLI::App& cmd, RunLimits& limits);

}  // namespace cairn
