#pragma once
/// The files of one run in its directory: trajectory.csv streamed while it runs (renamed
/// trajectory.partial.csv when it ends early) and run.json written last. Every command that writes
/// a run (`run`, `run-all`, validate's and compare's runs) writes them here.

#include <string>

#include "output/run_record.hpp"

namespace cairn {

constexpr const char* kTrajectoryFile = "trajectory.csv";          ///< a completed run's samples
constexpr const char* kPartialTrajectoryFile = "trajectory.partial.csv";   ///< a run that ended early
constexpr const char* kRunRecordFile = "run.json";                 ///< the run record

/// end the files of a run in `dir`, whose trajectory was streamed to dir/trajectory.csv: a run that
/// did not complete keeps its trajectory as trajectory.partial.csv; run.json is written last (atomic)
void finish_run_files(const std::string& dir, const Scene& scene, const Backend& backend,
                      const RunResult& result, const RunRequest& request);

}  // namespace cairn
