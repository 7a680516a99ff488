#pragma once
/// Merging a sweep's result files into one table (runs.csv, in expansion order: the same content
/// for any number of jobs, shards or their order), the wall times apart (timing.csv), and for a
/// fragility plan the fitted curves and the report.

#include <string>
#include <vector>

#include "sweep/sweep_runs.hpp"

namespace cairn::sweep {

/// What the merge found.
struct MergeSummary {
    std::size_t runs = 0;                 ///< runs in the sweep
    std::vector<std::string> missing;     ///< ids without a result file
    std::string note;                     ///< figures skipped and why, or ""
};

/// the result file of run `id` in `dir`
std::string result_path(const std::string& dir, const std::string& id);

/// the run directory of run `id` in `dir`
std::string run_dir(const std::string& dir, const std::string& id);

/// read every result of `sweep` in `dir`; write dir/runs.csv and dir/timing.csv (and, for a
/// fragility plan, fragility.csv, report.md, index.html and figures/) when none is missing.
/// Throws cairn::Error for a result file that cannot be read.
MergeSummary merge_sweep(const Sweep& sweep, const std::string& dir);

}  // namespace cairn::sweep
