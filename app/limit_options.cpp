#include "limit_options.hpp"

namespace cairn {

void add_limit_options(CLI::App& cmd, RunLimits& limits) {
    cmd.add_flag("--allow-large", limits.allow_large,
                 "accept more than 1e9 steps or 1e8 trajectory rows (a billion steps take hours of CPU; "
                 "1e8 rows are tens of GB of CSV)");
    cmd.add_flag("--allow-unstable-dt", limits.allow_unstable_dt,
                 "accept a given run.dt above the backend's critical step (the run will most likely blow up)");
    cmd.add_option("--memory-budget", limits.memory_budget,
                   "memory the model may take (meshes, mass matrices, hitting points), e.g. 8GiB; "
                   "default half of the machine's memory")
        ->transform(CLI::AsSizeValue(false))
        ->check(CLI::PositiveNumber);
}

}  // namespace cairn
