#pragma once
/// Running gnuplot for the compare layer's figures: one place that finds it, picks the PNG
/// terminal and runs a script, noting what failed instead of stopping the report.

#include <string>

namespace cairn::report {

/// true when gnuplot runs here; `note` explains otherwise (figures are then skipped)
bool gnuplot_available(std::string& note);

/// the PNG terminal: "pngcairo" when gnuplot has it, else "png"
const char* gnuplot_png_terminal();

/// run gnuplot on DIR/NAME.gp in DIR (its output in NAME.gp.log); false, with a line added to
/// `note`, when it fails
bool run_gnuplot_file(const std::string& dir, const std::string& name, std::string& note);

/// write `script` as DIR/NAME.gp and run gnuplot on it in DIR (its output in NAME.gp.log);
/// false, with a line added to `note`, when it fails
bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script, std::string& note);

}  // namespace cairn::report
