#include "report/gnuplot.hpp"

#include <cstdlib>
#include <filesystem>

#include "output/atomic_write.hpp"

namespace cairn::report {

bool gnuplot_available(std::string& note) {
    static const bool found = std::system("command -v gnuplot > /dev/null 2>&1") == 0;
    if (!found) note = "gnuplot was not found: no figures (install gnuplot-nox and rerun)";
    return found;
}

const char* gnuplot_png_terminal() {
    static const bool cairo = std::system("gnuplot -e 'set terminal pngcairo' > /dev/null 2>&1") == 0;
    return cairo ? "pngcairo" : "png";
}

bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script, std::string& note) {
    write_text_atomic((std::filesystem::path(dir) / (name + ".gp")).string(), script);
    return run_gnuplot_file(dir, name, note);
}

bool run_gnuplot_file(const std::string& dir, const std::string& name, std::string& note) {
    const std::string cmd = "cd '" + dir + "' && gnuplot '" + name + ".gp' > '" + name + ".gp.log' 2>&1";
    if (std::system(cmd.c_str()) == 0) return true;
    note += "gnuplot failed on figures/" + name + ".gp (see its .log). ";
    return false;
}

}  // namespace cairn::report
