#pragma once
/// A run directory written by `cairn run` read back as a replay: the scene named in run.json
/// (reloaded with the run's overrides) and the poses of trajectory.csv (or trajectory.partial.csv).

#include <string>

#include "report/replay.hpp"

namespace cairn {

/// the replay of the run in `dir`, labelled with its backend (and --model/--contact when given);
/// throws cairn::Error naming the file and what is wrong
ReplayRun replay_from_run_dir(const std::string& dir);

}  // namespace cairn
