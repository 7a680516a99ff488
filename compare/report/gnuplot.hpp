#pragma once
/// Running gnuplot for the compare layer's figures: one place that finds it, picks the PNG
/// terminal, runs a script (without a shell) and quotes text for its scripts, noting what failed
/// instead of stopping the report.

#include <string>

namespace cairn::report {

/// true when gnuplot runs here; `note` explains otherwise (figures are then skipped)
bool gnuplot_available(std::string& note);

/// the PNG terminal: "pngcairo" when gnuplot has it, else "png"
const char* gnuplot_png_terminal();

/// `s` as a gnuplot string literal that gnuplot reads back as the same text. Single-quoted:
/// gnuplot does no backslash escapes, no backquote command substitution and no `@` macro
/// expansion inside single quotes, and a `'` is written `''`. A newline (or any other control
/// character) would end the command, or join the next line after a backslash, so each becomes a
/// space. Titles, labels and names from scenes go through this and nothing else.
std::string gnuplot_string(const std::string& s);

/// a file name relative to the script's directory as a gnuplot string literal, prefixed with
/// "./": gnuplot reads a name starting with '<' (plot) or '|' (set output) as a shell command,
/// and '-', '+', '++' and '' as special files
std::string gnuplot_file(const std::string& name);

/// run gnuplot on DIR/NAME.gp in DIR (its output in NAME.gp.log); false, with a line added to
/// `note`, when it fails
bool run_gnuplot_file(const std::string& dir, const std::string& name, std::string& note);

/// write `script` as DIR/NAME.gp and run gnuplot on it in DIR (its output in NAME.gp.log);
/// false, with a line added to `note`, when it fails
bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script, std::string& note);

}  // namespace cairn::report
