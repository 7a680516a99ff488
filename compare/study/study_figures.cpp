// figures of the inertia study, drawn by gnuplot from data files written beside them
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "output/atomic_write.hpp"
#include "output/number_format.hpp"
#include "study/study_report.hpp"

#include "report/gnuplot.hpp"

namespace cairn::study {

namespace {

const std::vector<std::string> kSchemes{"barycentre", "lumped", "consistent", "corrected"};
const std::vector<std::string> kCases{"rocking", "rocking_slender", "impact"};

/// |x| in %, floored at 1e-4 % so that a log axis can show it
double pct(double x) { return std::isfinite(x) ? std::max(std::abs(x) * 100.0, 1e-4) : NAN; }

/// 10 significant digits, "NaN" for a missing number (gnuplot skips it)
std::string nan_dash(double v) { return number_format("%.10g", v, "NaN"); }

/// DIR/figures/inertia_<case>.dat: one index block per scheme, then the rigid point
void write_data(const std::string& path, const std::vector<StudyPoint>& pts, const std::string& c) {
    std::ostringstream o;
    o << "# n io_ratio io_closed_form event_err_pct wall_s element_updates ratio_err_pct\n";
    for (const auto& s : kSchemes) {
        o << "# " << s << "\n";
        for (const auto& p : pts)
            if (p.case_name == c && p.scheme == s)
                o << p.n << " " << nan_dash(p.io_ratio) << " " << nan_dash(p.io_closed_form) << " "
                  << nan_dash(pct(p.event_error())) << " " << nan_dash(p.wall_seconds) << " " << p.element_updates
                  << " " << nan_dash(std::isfinite(p.t_housner) ? pct(p.ratio_error()) : NAN) << "\n";
        o << "\n\n";
    }
    o << "# rigid\n";
    for (const auto& p : pts)
        if (p.case_name == c && p.scheme == "rigid")
            o << "1 1 1 " << nan_dash(pct(p.event_error())) << " " << nan_dash(p.wall_seconds) << " 0 "
              << nan_dash(std::isfinite(p.t_housner) ? pct(p.ratio_error()) : NAN) << "\n";
    write_text_atomic(path, o.str());
}

std::string plot_schemes(const std::string& dat, const std::string& using_cols, bool with_rigid_line) {
    std::ostringstream o;
    o << "plot ";
    for (size_t i = 0; i < kSchemes.size(); ++i)
        o << report::gnuplot_file(dat) << " index " << i << " using " << using_cols << " with linespoints ls "
          << i + 1 << " title " << report::gnuplot_string(kSchemes[i]) << ", ";
    if (with_rigid_line) o << report::gnuplot_file(dat) << " index 4 using (1):4 with points ls 5 title 'rigid (n = 1 axis)'";
    else o << "1/0 notitle";
    o << "\n";
    return o.str();
}

}  // namespace

std::vector<std::string> write_inertia_figures(const std::string& dir, const std::vector<StudyPoint>& pts,
                                               std::string& note) {
    namespace fs = std::filesystem;
    const fs::path fig = fs::path(dir) / "figures";
    fs::create_directories(fig);
    if (!report::gnuplot_available(note)) return {};
    for (const auto& c : kCases) write_data((fig / ("inertia_" + c + ".dat")).string(), pts, c);
    std::ostringstream head;
    head << "set terminal " << report::gnuplot_png_terminal() << " size 1500,480 font ',10'\n"
         << "set style line 1 lc rgb '#d62728' pt 7 lw 2\nset style line 2 lc rgb '#1f77b4' pt 5 lw 2\n"
         << "set style line 3 lc rgb '#2ca02c' pt 9 lw 2\nset style line 4 lc rgb '#9467bd' pt 11 lw 2 dt 2\n"
         << "set style line 5 lc rgb 'black' pt 3 ps 2\nset grid\nset key top right\n";
    const std::vector<std::string> titles{"rocking (reading B, 0.7 x 1.0 m)", "rocking\\_slender (0.2 x 1.0 m)",
                                          "impact (1 m cube, bounce period)"};
    struct Figure { std::string name, body; };
    std::vector<Figure> figures;
    {   // error against n
        std::ostringstream o;
        o << "set output 'inertia_error_n.png'\nset multiplot layout 1,3\nset logscale xy\nset xrange [0.8:10]\n"
          << "set xtics (1,2,4,8)\nset xlabel 'elements per side n'\nset format y '%g'\n";
        for (size_t i = 0; i < kCases.size(); ++i)
            o << "set title " << report::gnuplot_string(titles[i]) << "\nset ylabel '|"
              << (i < 2 ? "first-impact" : "bounce-period") << " error| %'\n" << plot_schemes("inertia_" + kCases[i] + ".dat", "1:4", true);
        o << "unset multiplot\n";
        figures.push_back({"inertia_error_n", o.str()});
    }
    {   // error against cost
        std::ostringstream o;
        o << "set output 'inertia_error_cost.png'\nset multiplot layout 1,3\nset logscale xy\n"
          << "set xlabel 'wall time per run, s (2 runs at a time on 2 cores)'\nset format y '%g'\n";
        for (size_t i = 0; i < kCases.size(); ++i)
            o << "set title " << report::gnuplot_string(titles[i]) << "\nset ylabel '|"
              << (i < 2 ? "first-impact" : "bounce-period") << " error| %'\nset label 1 'along each line: n = 1, 2, 4, 8' at graph 0.02,0.05\n"
              << plot_schemes("inertia_" + kCases[i] + ".dat", "5:4", false);
        o << "unset multiplot\n";
        figures.push_back({"inertia_error_cost", o.str()});
    }
    {   // I_O ratio against n, closed forms as lines
        std::ostringstream o;
        o << "set output 'inertia_io_ratio.png'\nset multiplot layout 1,2\nset logscale x\nset xrange [0.8:10]\n"
          << "set xtics (1,2,4,8)\nset xlabel 'elements per side n (mesh [n,1,n])'\n"
          << "set ylabel 'I_O / I_O,exact about the rocking edge'\nset key bottom right\n";
        for (size_t i = 0; i < 2; ++i) {
            const std::string dat = "inertia_" + kCases[i] + ".dat";
            o << "set title " << report::gnuplot_string(titles[i]) << "\nplot ";
            for (size_t s = 0; s < kSchemes.size(); ++s)
                o << report::gnuplot_file(dat) << " index " << s << " using 1:2 with points ls " << s + 1
                  << " ps 1.5 title " << report::gnuplot_string(kSchemes[s]) << ", ";
            o << "1 - 1/(4*x**2) + 0.25e-3 lc rgb '#d62728' dt 3 title '1 - 1/(4n^2)', "
              << "1 + 1/(2*x**2) lc rgb '#1f77b4' dt 3 title '1 + 1/(2n^2)'\n";
        }
        o << "unset multiplot\n";
        figures.push_back({"inertia_io_ratio", o.str()});
    }
    std::vector<std::string> out;
    for (const auto& f : figures) {
        if (report::run_gnuplot(fig.string(), f.name, head.str() + f.body, note))
            out.push_back("figures/" + f.name + ".png");
    }
    return out;
}

}  // namespace cairn::study
