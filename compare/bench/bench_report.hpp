#pragma once
/// The outputs of `cairn bench`: Pareto figures per case, a stability heat map per backend, and the
/// bench section (bench.md / bench.html) built from whatever of trade.csv, stability.csv and
/// wall.csv the output directory holds — a validation report may include bench_document(dir).

#include <string>
#include <vector>

#include "bench/stability.hpp"
#include "bench/trade_point.hpp"
#include "output/number_format.hpp"   // number_format, for the bench reports
#include "report/document.hpp"

namespace cairn::bench {

/// the error targets of the trade tables: 5 %, 1 %, 0.1 %
const std::vector<double>& error_targets();

/// DIR/figures/pareto_<case>.png (gnuplot: error against wall time, log-log, one colour per
/// variant, the front drawn); paths relative to DIR; `note` says why some are missing
std::vector<std::string> write_pareto_figures(const std::string& dir, const std::vector<TradePoint>& points,
                                              std::string& note);

/// DIR/figures/stability_<backend>.png: parameter × value → class
std::vector<std::string> write_stability_figures(const std::string& dir, const std::vector<StabilityPoint>& points,
                                                 std::string& note);

/// the table of one case: per variant, the cheapest configuration reaching each target or "cannot"
report::Table cheapest_table(const std::vector<TradePoint>& points, const std::string& case_name);

/// per backend and parameter, the values where it held and where it did not
report::Table stability_limits_table(const std::vector<StabilityPoint>& points);

/// the bench section from DIR's trade.csv, stability.csv and wall.csv (those that exist), figures
/// referenced relative to DIR
report::Document bench_document(const std::string& dir);

/// the whole text of a file ("" when it cannot be read)
std::string read_whole(const std::string& path);

/// write DIR/bench.md and DIR/bench.html from bench_document(dir)
void write_bench_report(const std::string& dir);

}  // namespace cairn::bench
