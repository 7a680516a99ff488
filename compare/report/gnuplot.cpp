#include "report/gnuplot.hpp"

#include <filesystem>

#include "output/atomic_write.hpp"
#include "report/spawn.hpp"

namespace cairn::report {

namespace {

/// gnuplot's full path on $PATH, looked up once
const std::string& gnuplot_path() {
    static const std::string path = find_on_path("gnuplot");
    return path;
}

}  // namespace

bool gnuplot_available(std::string& note) {
    const bool found = !gnuplot_path().empty();
    if (!found) note = "gnuplot was not found: no figures (install gnuplot-nox and rerun)";
    return found;
}

const char* gnuplot_png_terminal() {
    // gnuplot exits non-zero when `set terminal` names a terminal it does not have
    static const bool cairo =
        !gnuplot_path().empty() && run_program({gnuplot_path(), "-e", "set terminal pngcairo"}, "", "") == 0;
    return cairo ? "pngcairo" : "png";
}

std::string gnuplot_string(const std::string& s) {
    std::string o = "'";
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\'') o += "''";
        else if (u < 0x20 || u == 0x7f) o += ' ';
        else o += c;
    }
    return o + "'";
}

std::string gnuplot_file(const std::string& name) { return gnuplot_string("./" + name); }

bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script, std::string& note) {
    write_text_atomic((std::filesystem::path(dir) / (name + ".gp")).string(), script);
    return run_gnuplot_file(dir, name, note);
}

bool run_gnuplot_file(const std::string& dir, const std::string& name, std::string& note) {
    // "./" keeps a name starting with '-' from being read as an option
    if (!gnuplot_path().empty() && run_program({gnuplot_path(), "./" + name + ".gp"}, dir, name + ".gp.log") == 0)
        return true;
    note += "gnuplot failed on figures/" + name + ".gp (see its .log). ";
    return false;
}

}  // namespace cairn::report
