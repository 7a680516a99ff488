// figures of the benches, drawn by gnuplot from data files written beside them
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "bench/bench_report.hpp"

#include "report/gnuplot.hpp"
#include "output/atomic_write.hpp"

namespace fs = std::filesystem;

namespace cairn::bench {

namespace {

/// a colour per variant (backend first)
std::string colour(const std::string& variant) {
    static const std::map<std::string, std::string> c{{"dem-rigid", "#d62728"}, {"dem-deformable", "#ff7f0e"},
                                                      {"bullet", "#1f77b4"},    {"ode", "#2ca02c"},
                                                      {"mujoco", "#9467bd"}};
    auto it = c.find(variant);
    if (it != c.end()) return it->second;
    it = c.find(variant.substr(0, variant.find('-')));
    return it != c.end() ? it->second : "#7f7f7f";
}

/// 100·|e| floored at 1e-5 % for a log axis
double pct(double e) { return std::max(std::abs(e) * 100.0, 1e-5); }

}  // namespace

std::vector<std::string> write_pareto_figures(const std::string& dir, const std::vector<TradePoint>& points,
                                              std::string& note) {
    if (!report::gnuplot_available(note)) return {};
    const fs::path fig = fs::path(dir) / "figures";
    fs::create_directories(fig);
    std::vector<std::string> cases;
    for (const auto& p : points)
        if (std::find(cases.begin(), cases.end(), p.case_name) == cases.end()) cases.push_back(p.case_name);
    std::vector<std::string> out;
    for (const auto& c : cases) {
        std::vector<TradePoint> pts;
        for (const auto& p : points)
            if (p.case_name == c) pts.push_back(p);
        std::vector<std::string> variants;
        for (const auto& p : pts)
            if (std::find(variants.begin(), variants.end(), p.variant) == variants.end()) variants.push_back(p.variant);
        std::ostringstream dat;
        dat << "# wall_s error_pct (one block per variant, then the front)\n";
        for (const auto& v : variants) {
            dat << "# " << v << "\n";
            for (const auto& p : pts)
                if (p.variant == v && p.measured()) dat << p.wall_seconds << " " << pct(p.error) << "\n";
            dat << "\n\n";
        }
        dat << "# front\n";
        for (size_t i : pareto_front(pts)) dat << pts[i].wall_seconds << " " << pct(pts[i].error) << "\n";
        const std::string name = "pareto_" + c;
        write_text_atomic((fig / (name + ".dat")).string(), dat.str());
        std::ostringstream gp;
        gp << "set terminal " << report::gnuplot_png_terminal() << " size 900,620 font ',11'\n"
           << "set output " << report::gnuplot_file(name + ".png") << "\nset logscale xy\nset grid\nset key outside right top\n"
           << "set format y '%g'\nset format x '%g'\n"
           << "set title " << report::gnuplot_string(c + ": error against the oracle vs wall time (median of repeats)")
           << " noenhanced\n"
           << "set xlabel 'wall time of the run, s'\nset ylabel '|relative error|, % (floored at 1e-5 %)'\n"
           << "set arrow from graph 0, first 5 to graph 1, first 5 nohead dt 3 lc rgb 'gray'\n"
           << "set arrow from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb 'gray'\n"
           << "set arrow from graph 0, first 0.1 to graph 1, first 0.1 nohead dt 3 lc rgb 'gray'\nplot ";
        for (size_t i = 0; i < variants.size(); ++i)
            gp << report::gnuplot_file(name + ".dat") << " index " << i << " using 1:2 with points pt 7 ps 1.3 lc rgb "
               << report::gnuplot_string(colour(variants[i])) << " title " << report::gnuplot_string(variants[i]) << ", ";
        gp << report::gnuplot_file(name + ".dat") << " index " << variants.size()
           << " using 1:2 with steps lw 2 lc rgb 'black' title 'Pareto front'\n";
        if (report::run_gnuplot(fig.string(), name, gp.str(), note)) out.push_back("figures/" + name + ".png");
    }
    return out;
}

std::vector<std::string> write_stability_figures(const std::string& dir, const std::vector<StabilityPoint>& points,
                                                 std::string& note) {
    if (!report::gnuplot_available(note)) return {};
    const fs::path fig = fs::path(dir) / "figures";
    fs::create_directories(fig);
    std::vector<std::string> backends, params;
    for (const auto& p : points) {
        if (std::find(backends.begin(), backends.end(), p.backend) == backends.end()) backends.push_back(p.backend);
        if (std::find(params.begin(), params.end(), p.parameter) == params.end()) params.push_back(p.parameter);
    }
    std::vector<std::string> out;
    for (const auto& b : backends) {
        std::ostringstream dat;
        dat << "# column row class label\n";
        size_t width = 1;
        for (size_t r = 0; r < params.size(); ++r) {
            size_t col = 0;
            for (const auto& p : points)
                if (p.backend == b && p.parameter == params[r]) {
                    std::string label = p.value_text;
                    for (char& ch : label)   // a data-file string: no '"' inside, one line
                        if (ch == '"') ch = '\'';
                        else if (static_cast<unsigned char>(ch) < 0x20) ch = ' ';
                    dat << col++ << " " << r << " " << int(p.cls) << " \"" << label << "\"\n";
                }
            width = std::max(width, col);
        }
        const std::string name = "stability_" + b;
        write_text_atomic((fig / (name + ".dat")).string(), dat.str());
        std::ostringstream gp;
        gp << "set terminal " << report::gnuplot_png_terminal() << " size 1000," << 120 + 55 * params.size() << " font ',11'\n"
           << "set output " << report::gnuplot_file(name + ".png") << "\nunset key\nunset colorbox\nset xtics scale 0 format ''\n"
           << "set xrange [-0.5:" << width - 0.5 << "]\nset yrange [" << params.size() - 0.5 << ":-0.5]\n"
           << "set title " << report::gnuplot_string(b + ": green stable, red unstable, purple drifting, orange wrong, grey refused")
           << " noenhanced\n"
           << "set palette defined (0 '#2ca02c', 1 '#d62728', 2 '#9467bd', 3 '#ff9f1c', 4 '#b0b0b0')\n"
           << "set palette maxcolors 5\nset cbrange [-0.5:4.5]\nset style fill solid 1.0 border rgb 'white'\nset ytics (";
        for (size_t r = 0; r < params.size(); ++r) gp << (r ? ", " : "") << report::gnuplot_string(params[r]) << " " << r;
        gp << ") noenhanced\nset lmargin 16\n"
           << "plot " << report::gnuplot_file(name + ".dat") << " using 1:2:(0.5):(0.5):3 with boxxyerror fc palette, '' using 1:2:4 "
           << "with labels noenhanced font ',10'\n";
        if (report::run_gnuplot(fig.string(), name, gp.str(), note)) out.push_back("figures/" + name + ".png");
    }
    return out;
}

}  // namespace cairn::bench
