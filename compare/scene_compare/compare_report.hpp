#pragma once
/// The report of `cairn compare`: one scene on several variants, compared with each other (and with
/// the analytic reference when the scene has one). Writes the CSVs and figures into the output
/// directory and returns the document (report.md and index.html are its two renderings).

#include <string>
#include <vector>

#include "report/document.hpp"
#include "report/validation_report.hpp"
#include "validation/run_cases.hpp"

namespace cairn::scene_compare {

/// What the report shows beyond the runs.
struct CompareContext {
    std::string scene_label;        ///< the scene as the user named it
    std::string baseline;           ///< variant the others are compared with; empty = dem-rigid, else the first completed
    std::vector<BackendInfo> backends;   ///< capability rows of the engines used
    std::string command;            ///< the command line, for reproduction
    int jobs = 1;                   ///< runs at a time
    double wall_seconds = 0.0;      ///< wall time of the whole comparison, s
    int max_block_figures = 12;     ///< figures for at most this many free blocks (CSV for all)
};

/// The variant the others are compared with.
struct Baseline {
    const validation::CaseRun* run = nullptr;   ///< null: no run completed
    std::string why;                            ///< how it was chosen
};

/// `context.baseline` if it completed, else dem-rigid, else the first completed run
Baseline choose_baseline(const validation::CaseResult& result, const std::string& wanted);

/// write DIR/data/*.csv (histories, differences, energies), DIR/differences.csv, DIR/energy.csv
/// and DIR/figures/*.png, and return the report; `figure_note` says why figures are missing
report::Document write_compare_report(const validation::CaseResult& result, const CompareContext& context,
                                      const std::string& dir, std::string& figure_note);

}  // namespace cairn::scene_compare
