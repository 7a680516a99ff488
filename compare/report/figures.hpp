#pragma once
/// The report's figures, drawn by gnuplot from data files and scripts written into the output
/// directory: per case every variant over the analytic curve with a difference panel, and for the
/// rolling case snapshots of the cube on the incline.

#include <map>
#include <string>
#include <vector>

#include "validation/run_cases.hpp"

namespace cairn::report {

/// The figures written, by case.
struct FigureSet {
    std::map<std::string, std::vector<std::string>> images;   ///< case → PNG paths relative to the output dir
    std::string note;                                          ///< why there are none (gnuplot missing) or ""
};

/// write DIR/figures/<case>*.dat and .gp and run gnuplot on them (pngcairo, else png)
FigureSet write_figures(const std::vector<validation::CaseResult>& cases, const std::string& dir);

}  // namespace cairn::report
