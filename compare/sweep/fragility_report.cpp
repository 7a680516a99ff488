// fragility curves of a merged sweep: fits, figures, report
#include "sweep/fragility_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "output/atomic_write.hpp"
#include "report/document.hpp"
#include "report/gnuplot.hpp"
#include "report/palette.hpp"
#include "report/text.hpp"
#include "sweep/fragility.hpp"

namespace fs = std::filesystem;

namespace cairn::sweep {

namespace {

/// 10 significant digits unless told, "" for NaN or infinity
std::string num(double v, int digits = 10) { return number_text(v, digits); }

/// One curve: the runs of one scene and axis-value combination on one backend.
struct Group {
    std::string scene, axes, backend;          // axes: "key=value, ..." or ""
    std::vector<FragilityPoint> points;        // completed runs
    std::vector<size_t> runs;                  // indices into the sweep (all of the group's runs)
    int excluded = 0;                          // runs that did not complete
    FragilityFit fit;
};

std::string axes_text(const Sweep& s, const SweepRun& r) {
    std::string out;
    for (size_t a = 0; a < r.axis_values.size(); ++a)
        out += (out.empty() ? "" : ", ") + s.plan.axes[a].key + " = " + r.axis_values[a];
    return out;
}

/// per record and backend the lowest intensity that overturned the block (and whether a higher one
/// did not), and how often the backends agree on the outcome of the same point
void write_record_tables(const Sweep& sweep, const std::vector<SweepResult>& results, report::Document& d) {
    std::vector<std::string> backends = sweep.plan.backends, records;
    // point (everything but the backend) → outcome per backend ("1", "0", or the status)
    std::map<std::string, std::map<std::string, std::string>> points;
    std::map<std::string, std::map<std::string, std::pair<double, bool>>> lowest;   // record, backend → x, non-monotonic
    std::vector<std::string> order;
    for (size_t i = 0; i < sweep.runs.size(); ++i) {
        const auto& run = sweep.runs[i];
        const std::string rec = run.scene_name + (axes_text(sweep, run).empty() ? "" : " (" + axes_text(sweep, run) + ")") +
                                ": " + run.record;
        if (std::find(records.begin(), records.end(), rec) == records.end()) records.push_back(rec);
        const std::string point = rec + "\n" + num(run.intensity, 17) + "\n" + std::to_string(run.repeat);
        if (!points.count(point)) order.push_back(point);
        const bool ok = results[i].status == "completed";
        points[point][run.backend] = ok ? (results[i].overturned ? "1" : "0") : results[i].status;
        if (ok && results[i].overturned) {
            auto it = lowest[rec].find(run.backend);
            if (it == lowest[rec].end() || run.intensity < it->second.first) lowest[rec][run.backend] = {run.intensity, false};
        }
    }
    // a survivor above the lowest overturning intensity: the outcome is not monotonic in intensity
    for (size_t i = 0; i < sweep.runs.size(); ++i) {
        const auto& run = sweep.runs[i];
        const std::string rec = run.scene_name + (axes_text(sweep, run).empty() ? "" : " (" + axes_text(sweep, run) + ")") +
                                ": " + run.record;
        auto it = lowest[rec].find(run.backend);
        if (it != lowest[rec].end() && results[i].status == "completed" && !results[i].overturned &&
            run.intensity > it->second.first)
            it->second.second = true;
    }
    report::Table t;
    t.header = {"record"};
    for (const auto& b : backends) t.header.push_back(b);
    for (const auto& rec : records) {
        std::vector<std::string> row{rec};
        for (const auto& b : backends) {
            auto it = lowest[rec].find(b);
            row.push_back(it == lowest[rec].end() ? "none" : num(it->second.first, 4) + " g" + (it->second.second ? " (survives above)" : ""));
        }
        t.rows.push_back(row);
    }
    d.heading(2, "Lowest overturning intensity");
    d.paragraph("Per record, the lowest peak ground acceleration of the plan at which each backend overturned the block; "
                "\"survives above\" marks a record under which the block stands again at a higher intensity.");
    d.table(t);
    if (backends.size() > 1) {
        int agree = 0, total = 0;
        std::vector<std::string> split;
        for (const auto& p : order) {
            const auto& by = points[p];
            if (by.size() != backends.size()) continue;
            ++total;
            bool same = true;
            for (const auto& [b, v] : by) same = same && v == by.begin()->second;
            if (same) ++agree;
            else {
                std::string line = p.substr(0, p.find('\n')) + " at " + num(std::stod(p.substr(p.find('\n') + 1)), 4) + " g:";
                for (const auto& [b, v] : by) line += " " + b + " " + (v == "1" ? "overturned" : v == "0" ? "stood" : v);
                split.push_back(line);
            }
        }
        d.heading(2, "Agreement between backends");
        d.paragraph(std::to_string(agree) + " of " + std::to_string(total) +
                    " points (record, intensity, axis values, repeat) have the same outcome on every backend" +
                    (split.empty() ? "." : "; the others:"));
        if (!split.empty()) d.bullets(split);
    }
}

}  // namespace

std::string write_fragility_report(const Sweep& sweep, const std::vector<SweepResult>& results, const std::string& dir) {
    // the groups, in the order they first appear
    std::vector<Group> groups;
    std::map<std::string, size_t> where;
    for (size_t i = 0; i < sweep.runs.size(); ++i) {
        const auto& run = sweep.runs[i];
        const std::string key = run.scene_name + "\n" + axes_text(sweep, run) + "\n" + run.backend;
        auto it = where.find(key);
        if (it == where.end()) {
            it = where.emplace(key, groups.size()).first;
            groups.push_back(Group{run.scene_name, axes_text(sweep, run), run.backend, {}, {}, 0, {}});
        }
        Group& g = groups[it->second];
        g.runs.push_back(i);
        if (results[i].status == "completed") g.points.push_back({run.intensity, results[i].overturned});
        else ++g.excluded;
    }
    for (auto& g : groups) g.fit = fit_lognormal_fragility(g.points);

    std::ostringstream csv;
    csv << "scene,axes,backend,runs,failures,excluded,status,theta_g,beta,se_ln_theta,se_beta,log_likelihood\n";
    for (const auto& g : groups)
        csv << report::csv_field(g.scene) << "," << report::csv_field(g.axes) << "," << g.backend << "," << g.fit.runs
            << "," << g.fit.failures << "," << g.excluded << "," << g.fit.status << "," << num(g.fit.theta) << ","
            << num(g.fit.beta) << "," << num(g.fit.se_ln_theta) << "," << num(g.fit.se_beta) << ","
            << num(g.fit.log_likelihood) << "\n";
    write_text_atomic((fs::path(dir) / "fragility.csv").string(), csv.str());

    // figures: per scene and axis values, the observed fractions and fitted curves of every backend,
    // and the peak rotation over the overturning angle against intensity (incremental dynamic analysis)
    std::string note;
    std::vector<std::pair<std::string, std::string>> images;   // path, caption
    const fs::path fig = fs::path(dir) / "figures";
    fs::create_directories(fig);
    std::vector<std::string> panels;   // scene + axes, in order
    for (const auto& g : groups) {
        const std::string p = g.scene + (g.axes.empty() ? "" : " (" + g.axes + ")");
        if (std::find(panels.begin(), panels.end(), p) == panels.end()) panels.push_back(p);
    }
    if (report::gnuplot_available(note)) {
        for (size_t p = 0; p < panels.size(); ++p) {
            const std::string stem = "fragility_" + std::to_string(p + 1), ida = "ida_" + std::to_string(p + 1);
            std::ostringstream data, gp, ida_data, ida_gp;
            double xmax = 0.0;
            std::vector<const Group*> mine;
            for (const auto& g : groups)
                if (g.scene + (g.axes.empty() ? "" : " (" + g.axes + ")") == panels[p]) mine.push_back(&g);
            for (const Group* g : mine) {
                // observed fraction per intensity
                std::map<double, std::pair<int, int>> frac;
                for (const auto& pt : g->points) {
                    auto& f = frac[pt.intensity];
                    f.first += pt.failed ? 1 : 0;
                    ++f.second;
                    xmax = std::max(xmax, pt.intensity);
                }
                data << "# " << g->backend << "\n";
                for (const auto& [x, f] : frac) data << num(x) << " " << num(double(f.first) / f.second) << "\n";
                data << "\n\n";
                ida_data << "# " << g->backend << "\n";
                for (size_t i : g->runs)
                    if (results[i].status == "completed")
                        ida_data << num(sweep.runs[i].intensity) << " "
                                 << num(std::min(results[i].peak_rotation / sweep.runs[i].overturn_angle, 3.0)) << "\n";
                ida_data << "\n\n";
            }
            write_text_atomic((fig / (stem + ".dat")).string(), data.str());
            write_text_atomic((fig / (ida + ".dat")).string(), ida_data.str());
            const std::string head = std::string("set terminal ") + report::gnuplot_png_terminal() +
                                     " noenhanced size 900,600 font ',11'\nset grid\nset key below\n";
            gp << head << "set output " << report::gnuplot_file(stem + ".png") << "\nset title "
               << report::gnuplot_string("fragility: " + panels[p]) << "\nset xlabel 'peak ground acceleration (g)'\n"
               << "set ylabel 'P(overturn)'\nset yrange [-0.05:1.05]\nset xrange [0:" << num(xmax * 1.1) << "]\n"
               << "set samples 400\nplot ";
            ida_gp << head << "set output " << report::gnuplot_file(ida + ".png") << "\nset title "
                   << report::gnuplot_string("peak rotation: " + panels[p]) << "\nset xlabel 'peak ground acceleration (g)'\n"
                   << "set ylabel 'peak rotation / overturning angle (capped at 3)'\nset yrange [0:3.1]\nplot ";
            for (size_t k = 0; k < mine.size(); ++k) {
                const Group& g = *mine[k];
                // the backend's colour in every report (rigid contact: the sweep runs the scene as written)
                const std::string c = report::variant_colour(
                    g.backend.find('-') != std::string::npos ? g.backend : g.backend == "dem" ? "dem-rigid" : g.backend + "-rigid");
                gp << report::gnuplot_file(stem + ".dat") << " index " << k << " using 1:2 with points pt 7 ps 1.3 lc rgb '"
                   << c << "' title " << report::gnuplot_string(g.backend + " observed") << ", ";
                if (g.fit.status == "fitted")
                    gp << "(x > 0 ? norm((log(x) - log(" << num(g.fit.theta, 17) << ")) / " << num(g.fit.beta, 17)
                       << ") : 0) with lines lw 2 lc rgb '" << c << "' title "
                       << report::gnuplot_string(g.backend + " lognormal θ = " + num(g.fit.theta, 3) + " g, β = " +
                                                 num(g.fit.beta, 3))
                       << ", ";
                else if (g.fit.status == "separated")
                    gp << "(x < " << num(g.fit.theta, 17) << " ? 0 : 1) with lines lw 2 dt 2 lc rgb '" << c << "' title "
                       << report::gnuplot_string(g.backend + " step at " + num(g.fit.theta, 3) + " g (separated)") << ", ";
                ida_gp << report::gnuplot_file(ida + ".dat") << " index " << k << " using 1:2 with points pt 7 lc rgb '"
                       << c << "' title " << report::gnuplot_string(g.backend) << ", ";
            }
            gp << "1/0 notitle\n";
            ida_gp << "1 with lines dt 2 lc rgb 'black' title 'overturning angle'\n";
            if (report::run_gnuplot(fig.string(), stem, gp.str(), note))
                images.push_back({"figures/" + stem + ".png", "Fragility, " + panels[p] +
                                                                   ": the fraction of runs that overturned at each "
                                                                   "intensity (points) and the fitted lognormal curve"});
            if (report::run_gnuplot(fig.string(), ida, ida_gp.str(), note))
                images.push_back({"figures/" + ida + ".png", "Incremental dynamic analysis, " + panels[p] +
                                                                 ": each run's peak rotation over the overturning angle"});
        }
    }

    report::Document d;
    d.title = "cairn sweep: fragility";
    d.paragraph("Plan " + fs::path(sweep.plan.path).filename().string() + ": " + std::to_string(sweep.runs.size()) +
                " runs; every run in runs.csv. A run counts as overturned when the block's final tilt exceeds its "
                "overturning angle (atan of base over height unless the plan sets overturn_angle).");
    d.paragraph("The curves are lognormal, P(overturn | x) = Φ((ln x − ln θ)/β) with x the peak ground acceleration of "
                "the scaled record, fitted by maximum likelihood to the 0/1 outcome of every completed run (a "
                "binomial likelihood, probit regression on ln x by Fisher scoring). Standard errors come from the "
                "inverse Fisher information (delta method for θ and β). When every survivor lies below every "
                "overturned run the likelihood has no maximum (β → 0); the curve is then a step at the geometric "
                "mean of the two neighbouring intensities and is marked separated.");
    {
        report::Table t;
        t.header = {"scene", "axes", "backend", "runs", "overturned", "not completed", "fit", "θ (g)", "β",
                    "SE ln θ", "SE β"};
        for (const auto& g : groups)
            t.rows.push_back({g.scene, g.axes.empty() ? "-" : g.axes, g.backend, std::to_string(g.fit.runs),
                              std::to_string(g.fit.failures), std::to_string(g.excluded), g.fit.status,
                              num(g.fit.theta, 4), num(g.fit.beta, 3), num(g.fit.se_ln_theta, 3), num(g.fit.se_beta, 3)});
        d.heading(2, "Fragility curves");
        d.table(t);
    }
    for (const auto& [path, caption] : images) d.image(path, caption);
    write_record_tables(sweep, results, d);
    {
        report::Table t;
        t.header = {"record", "source"};
        if (sweep.plan.records.empty()) t.rows.push_back({"scene", "each scene's own [ground_motion]"});
        for (const auto& r : sweep.plan.records) t.rows.push_back({r.name, r.source});
        d.heading(2, "Records");
        d.table(t);
    }
    if (!note.empty()) d.paragraph("Figures: " + note);
    write_text_atomic((fs::path(dir) / "report.md").string(), report::to_markdown(d));
    write_text_atomic((fs::path(dir) / "index.html").string(), report::to_html(d));
    return note;
}

}  // namespace cairn::sweep
