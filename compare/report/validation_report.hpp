#pragma once
/// The outputs of `cairn validate`: summary.csv, report.md / index.html, and the terminal verdict.

#include <map>
#include <string>
#include <vector>

#include "backend/backend_info.hpp"
#include "report/document.hpp"
#include "report/figures.hpp"
#include "validation/run_cases.hpp"

namespace cairn::report {

/// Everything the report shows beyond the runs.
struct ReportContext {
    std::vector<BackendInfo> backends;   ///< the capability matrix: the backends used
    double wall_seconds = 0.0;                   ///< wall time of the whole validation, s
    int jobs = 1;                                ///< threads used
    std::string command;                         ///< the command line, for reproduction
    std::map<std::string, std::string> replays;  ///< case → its 3-D replay page, relative to the output dir
    std::string replay_note;                     ///< why a case has no replay page, or ""
};

/// verdict of a run: "pass k/k" (", n not comparable" when some metrics are), "miss j/k", "not
/// comparable" (no metric its references can judge), "cannot represent", "failed", "unstable",
/// "no metrics"
std::string run_verdict(const validation::CaseRun& r);

/// the verdict grid's cell of a run: "pass", "miss" (each followed by " (n n.c.)" when n metrics are
/// not comparable), "n.c.", or the run's outcome
std::string verdict_cell(const validation::CaseRun& r);

/// the metric of a run that misses by the most (relative to its tolerance), as one line; the
/// message for a run without metrics
std::string worst_metric_text(const validation::CaseRun& r);

/// the table of every metric of every run (case, variant, backend, contact mode, model, metric,
/// unit, value, reference, relative error, tolerance, pass, wall seconds, status)
std::string summary_csv(const std::vector<validation::CaseResult>& cases);

/// the report: verdict table, conventions, per case figures and tables, capability matrix
Document build_report(const std::vector<validation::CaseResult>& cases, const FigureSet& figures,
                      const ReportContext& context);

/// the verdict for the terminal: one line per case × variant with its worst metric
std::string verdict_text(const std::vector<validation::CaseResult>& cases);

}  // namespace cairn::report
