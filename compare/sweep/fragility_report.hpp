#pragma once
/// The fragility part of a merged sweep: the lognormal fit per scene, axis values and backend
/// (fragility.csv), the curves and the incremental dynamic analysis figures, and the report
/// (report.md and index.html).

#include <string>
#include <vector>

#include "sweep/sweep_result.hpp"

namespace cairn::sweep {

/// write DIR/fragility.csv, DIR/figures/, DIR/report.md and DIR/index.html from the results (one
/// per run, in the sweep's order); returns why figures are missing, or ""
std::string write_fragility_report(const Sweep& sweep, const std::vector<SweepResult>& results, const std::string& dir);

}  // namespace cairn::sweep
