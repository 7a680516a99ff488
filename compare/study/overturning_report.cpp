// writing the overturning study: CSV tables, the overturning-spectrum figure, markdown and HTML
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "output/atomic_write.hpp"
#include "report/document.hpp"
#include "report/gnuplot.hpp"
#include "report/text.hpp"
#include "study/overturning_study.hpp"

namespace cairn::study {

namespace {

std::string n10(double v) { return report::number_text(v, 10); }

std::string fixed(double v, int digits) { return std::isfinite(v) ? report::fixed_text(v, digits) : "–"; }


const Boundary* find_boundary(const OverturningResult& r, const std::string& method, double ratio) {
    for (const auto& b : r.boundaries)
        if (b.method == method && b.ratio == ratio) return &b;
    return nullptr;
}

bool oracle_verdict(const OverturningResult& r, double ratio, double level, bool& found) {
    for (const auto& g : r.grid)
        if (g.method == "oracle" && g.ratio == ratio && g.level == level) {
            found = g.status == "completed";
            return g.overturned;
        }
    found = false;
    return false;
}

std::vector<std::string> write_figure(const std::string& dir, const OverturningSetup& s, const OverturningResult& r,
                                      std::string& note) {
    namespace fs = std::filesystem;
    const fs::path fig = fs::path(dir) / "figures";
    fs::create_directories(fig);
    if (!report::gnuplot_available(note)) return {};
    std::ostringstream d;
    d << "# oracle boundary: ratio level\n";
    for (size_t i = 0; i < r.fine_ratios.size(); ++i)
        if (std::isfinite(r.fine_levels[i])) d << r.fine_ratios[i] << " " << n10(r.fine_levels[i]) << "\n";
    d << "\n\n# oracle grid overturned\n";
    for (const auto& g : r.grid)
        if (g.method == "oracle" && g.overturned) d << g.ratio << " " << g.level << "\n";
    d << "\n\n";
    // one block per backend: its bisected minimum (offset a little in frequency to be seen)
    for (size_t k = 0; k < s.backends.size(); ++k) {
        d << "# " << s.backends[k] << "\n";
        for (const auto& b : r.boundaries)
            if (b.method == s.backends[k] && b.found() && b.note.empty())
                d << b.ratio + 0.06 * (double(k) - 1.5) << " " << n10(b.level()) << "\n";
        d << "\n\n";
    }
    // disagreements of the grid verdicts with the oracle
    d << "# disagreements\n";
    for (const auto& g : r.grid) {
        bool found = false;
        const bool o = oracle_verdict(r, g.ratio, g.level, found);
        if (g.method != "oracle" && found && g.status == "completed" && g.overturned != o)
            d << g.ratio << " " << g.level << "\n";
    }
    d << "\n\n";
    write_text_atomic((fig / "overturning.dat").string(), d.str());
    std::ostringstream gp;
    gp << "set terminal " << report::gnuplot_png_terminal() << " size 1000,650 font ',10'\n"
       << "set output 'overturning.png'\nset grid\nset key top left\nset logscale y\n"
       << "set xlabel 'pulse frequency w_p / p'\nset ylabel 'pulse amplitude a_p / (g tan a)'\n"
       << "set title " << report::gnuplot_string(std::string("overturning spectrum, one ") + to_string(s.pulse) +
                                                 " pulse: oracle boundary, each backend's bisected minimum")
       << " noenhanced\n";
    const char* colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#8c564b", "#e377c2"};
    const char* points[] = {"7", "5", "9", "11", "13", "3"};
    gp << "plot " << report::gnuplot_file("overturning.dat") << " index 1 using 1:2 with points pt 6 ps 1.5 lc rgb "
       << "'#bbbbbb' title 'oracle: overturned (grid)', " << report::gnuplot_file("overturning.dat")
       << " index 0 using 1:2 with lines lw 2 lc rgb 'black' title 'oracle: minimum overturning amplitude'";
    for (size_t k = 0; k < s.backends.size(); ++k)
        gp << ", " << report::gnuplot_file("overturning.dat") << " index " << k + 2 << " using 1:2 with points pt "
           << points[k % 6] << " ps 1.3 lc rgb '" << colours[k % 6] << "' title "
           << report::gnuplot_string(s.backends[k]);
    gp << ", " << report::gnuplot_file("overturning.dat") << " index " << s.backends.size() + 2
       << " using 1:2 with points pt 2 ps 2 lc rgb 'red' title 'a backend disagrees with the oracle (grid)'\n";
    if (!report::run_gnuplot(fig.string(), "overturning", gp.str(), note)) return {};
    return {"figures/overturning.png"};
}

}  // namespace

void write_overturning_study(const std::string& dir, const OverturningSetup& s, const OverturningResult& r) {
    namespace fs = std::filesystem;
    write_file_atomic((fs::path(dir) / "overturning.csv").string(), [&](std::ostream& o) {
        o << "phase,method,ratio,level,overturned,max_theta,wall_seconds,status\n";
        for (const auto& g : r.grid)
            o << "grid," << g.method << "," << n10(g.ratio) << "," << n10(g.level) << "," << int(g.overturned) << ","
              << n10(g.max_theta) << "," << n10(g.wall_seconds) << "," << report::csv_field(g.status) << "\n";
        for (const auto& g : r.bisection)
            o << "bisection," << g.method << "," << n10(g.ratio) << "," << n10(g.level) << "," << int(g.overturned)
              << "," << n10(g.max_theta) << "," << n10(g.wall_seconds) << "," << report::csv_field(g.status) << "\n";
    });
    write_file_atomic((fs::path(dir) / "overturning_boundary.csv").string(), [&](std::ostream& o) {
        o << "method,ratio,lo,hi,level,error_vs_oracle,note\n";
        for (const auto& b : r.boundaries) {
            const Boundary* ob = find_boundary(r, "oracle", b.ratio);
            const double err = ob && ob->found() && b.found() && b.note.empty() ? b.level() / ob->level() - 1.0 : NAN;
            o << b.method << "," << n10(b.ratio) << "," << n10(b.lo) << "," << n10(b.hi) << ","
              << n10(b.found() ? b.level() : NAN) << "," << n10(err) << "," << report::csv_field(b.note) << "\n";
        }
    });
    std::string note;
    const auto figures = write_figure(dir, s, r, note);

    const auto o = setup_oracle(s);
    report::Document doc;
    doc.title = "cairn: overturning study";
    doc.heading(2, "Overturning under one " + std::string(to_string(s.pulse)) + " pulse");
    doc.paragraph("Block " + fixed(2 * s.b, 3) + " m wide (x) and " + fixed(2 * s.h, 3) + " m high: alpha = " +
                  fixed(o.alpha(), 5) + " rad, p = " + fixed(o.p(), 5) + " 1/s, Housner's r = " +
                  fixed(o.housner_restitution(), 5) + ". Scene: " + s.scene_source + ". Each point is a pulse of " +
                  "amplitude a_p (as a multiple of g tan alpha) and frequency w_p (as a multiple of p), run on every " +
                  "backend and on the rocking oracle (Housner's equation with located impacts, docs/validation.md). " +
                  "A backend run counts as overturned once |theta| passes 60 degrees; it is safe once, after the pulse, " +
                  "its energy above rest is below half of m g R (1 - cos alpha). The minimum overturning amplitude " +
                  "is bisected " + std::to_string(s.bisect) + " times from each method's own grid bracket.");
    {
        // the in-house engine's contact, on which its error depends (the other engines' own contacts ignore it)
        const ContactLaw c = parse_scene(s.scene_text, s.scene_source, s.overrides).contact;
        std::string text = "Contact of the in-house engine (dem): scheme " + std::string(to_string(c.scheme));
        if (c.scheme == ContactScheme::paper) text += ", hitting points at most " + report::number_text(c.grid_spacing, 6) + " m apart";
        text += ", kn " + report::number_text(c.kn, 6) + " N/m3, ks " + report::number_text(c.ks, 6) + " N/m3, ";
        if (c.damping_rule == ContactDampingRule::none) text += "no contact damping";
        else if (c.damping_rule == ContactDampingRule::ratio) text += "damping ratio " + report::number_text(c.damping, 6);
        else text += "damping time " + report::number_text(c.damping, 6) + " s";
        text += ", friction " + report::number_text(c.friction, 6) + ".";
        doc.paragraph(text);
    }
    for (const auto& f : figures) doc.image(f, "overturning spectrum: the oracle's boundary and each backend's minimum");
    if (!note.empty()) doc.paragraph("Figures: " + note);

    doc.heading(3, "Minimum overturning amplitude a_p / (g tan alpha) and error against the oracle");
    report::Table t;
    t.header = {"w_p / p", "oracle"};
    for (const auto& m : s.backends) t.header.push_back(m);
    std::map<std::string, double> worst;
    for (double w : s.ratios) {
        const Boundary* ob = find_boundary(r, "oracle", w);
        std::vector<std::string> row{fixed(w, 2), ob && ob->found() ? fixed(ob->level(), 4) : "–"};
        for (const auto& m : s.backends) {
            const Boundary* b = find_boundary(r, m, w);
            if (!b || !b->found() || !b->note.empty()) {
                row.push_back(b && !b->note.empty() ? b->note : "–");
                continue;
            }
            std::string cell = fixed(b->level(), 4);
            if (ob && ob->found()) {
                const double e = b->level() / ob->level() - 1.0;
                cell += " (" + std::string(e >= 0 ? "+" : "") + fixed(100.0 * e, 2) + " %)";
                worst[m] = std::max(worst[m], std::abs(e));
                // where the oracle flips more than once, the error against its nearest flip too
                double nearest = NAN;
                for (double f : ob->flips)
                    if (!std::isfinite(nearest) || std::abs(f - b->level()) < std::abs(nearest - b->level())) nearest = f;
                if (ob->flips.size() > 1 && std::isfinite(nearest) && std::abs(nearest / ob->level() - 1.0) > 1e-3)
                    cell += "; " + std::string(b->level() >= nearest ? "+" : "") +
                            fixed(100.0 * (b->level() / nearest - 1.0), 2) + " % from the oracle's flip at " +
                            fixed(nearest, 3);
            }
            row.push_back(cell);
        }
        t.rows.push_back(row);
    }
    doc.table(t);

    doc.heading(3, "Agreement of the grid verdicts with the oracle");
    report::Table a;
    a.header = {"backend", "agreeing points", "fraction", "largest |error| of the minimum", "failed runs"};
    for (const auto& m : s.backends) {
        int agree = 0, total = 0, failed = 0;
        for (const auto& g : r.grid) {
            if (g.method != m) continue;
            bool found = false;
            const bool ov = oracle_verdict(r, g.ratio, g.level, found);
            if (g.status != "completed") {
                ++failed;
                continue;
            }
            if (!found) continue;
            ++total;
            agree += g.overturned == ov;
        }
        a.rows.push_back({m, std::to_string(agree) + " / " + std::to_string(total),
                          total ? fixed(double(agree) / total, 3) : "–",
                          worst.count(m) ? fixed(100.0 * worst[m], 2) + " %" : "–", std::to_string(failed)});
    }
    doc.table(a);
    doc.heading(3, "Where the oracle is not monotonic");
    if (r.non_monotonic.empty())
        doc.paragraph("At every grid frequency the oracle's verdict flips once between 0.8 and 1.2 times its minimum "
                      "overturning amplitude.");
    else
        doc.bullets(r.non_monotonic);
    doc.paragraph("Far above the minimum every frequency has a safe band (the block is thrown one way, hits, and the "
                  "pulse's second half stops it: the two overturning modes of the one-sine pulse); the grid "
                  "verdicts there compare that band too. The bisection starts from each method's first overturning "
                  "grid point, so an overturning island below the grid's resolution is missed by all methods alike.");
    double wall = 0.0;
    for (const auto& g : r.grid) wall += g.wall_seconds;
    for (const auto& g : r.bisection) wall += g.wall_seconds;
    doc.paragraph("Backend runs: " + std::to_string(r.grid.size() - s.ratios.size() * s.levels.size()) + " grid + " +
                  std::to_string(r.bisection.size()) + " bisection, " + fixed(wall, 1) + " s of run time; study wall " +
                  "time " + fixed(r.wall_seconds, 1) + " s with " + std::to_string(s.jobs) + " jobs.");
    write_text_atomic((fs::path(dir) / "overturning.md").string(), report::to_markdown(doc));
    write_text_atomic((fs::path(dir) / "overturning.html").string(), report::to_html(doc));
}

}  // namespace cairn::study
