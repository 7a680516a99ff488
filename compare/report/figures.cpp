#include "report/figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "geometry/hexahedron.hpp"
#include "report/gnuplot.hpp"
#include "report/palette.hpp"
#include "metrics/signal.hpp"
#include "output/atomic_write.hpp"

namespace fs = std::filesystem;

namespace cairn::report {

namespace {

std::string terminal() {
    return std::string(gnuplot_png_terminal()) + " noenhanced size 1000,760 font 'sans,10'";
}

/// t, measured, analytic (or NaN), difference (to the analytic curve, else to the first run)
std::string curve_data(const validation::CaseRun& r, const validation::CaseRun* base) {
    std::ostringstream o;
    o.precision(10);
    const auto& a = r.analysis;
    o << "# t measured analytic difference\n";
    for (size_t i = 0; i < a.measured.t.size(); ++i) {
        double t = a.measured.t[i], y = a.measured.y[i];
        double ref = i < a.analytic.size() ? a.analytic[i] : NAN;
        double diff = std::isfinite(ref) ? y - ref : (base ? y - metrics::interpolate(base->analysis.measured, t) : NAN);
        o << t << " " << y << " " << ref << " " << diff << "\n";
    }
    return o.str();
}

/// outline in the x-z plane of the corners 0, 1, 5, 4 (a block's −y side face), closed
void outline(std::ostream& o, const std::array<Vec3, 8>& w) {
    for (int i : {0, 1, 5, 4, 0}) o << w[i].x() << " " << w[i].z() << "\n";
    o << "\n";
}

/// snapshots of the reference block every `every` seconds, and the fixed blocks
std::string snapshot_data(const Scene& scene, const validation::CaseRun& r, double every, int max_shots) {
    std::ostringstream o;
    o.precision(8);
    const int a = scene.reference->block;
    const BlockDef& d = scene.blocks[a];
    const Vec3 centre = mass_properties(d.corners, scene.materials[d.material].density).centre;
    int f = 0;
    for (int i = 0; i < a; ++i) f += scene.blocks[i].fixed ? 0 : 1;
    double next = 0.0;
    int shots = 0;
    for (const auto& s : r.samples) {
        if (s.t + 1e-9 < next || shots >= max_shots) continue;
        std::array<Vec3, 8> w;
        for (int i = 0; i < 8; ++i) w[i] = s.blocks[f].position + s.blocks[f].orientation * (d.corners[i] - centre);
        outline(o, w);
        next += every;
        ++shots;
    }
    return o.str();
}

std::string fixed_outline(const Scene& scene) {
    std::ostringstream o;
    for (const auto& b : scene.blocks) {
        if (!b.fixed) continue;
        std::array<Vec3, 8> w;
        for (int i = 0; i < 8; ++i) w[i] = b.position + b.orientation * b.corners[i];
        outline(o, w);
    }
    return o.str();
}


}  // namespace

FigureSet write_figures(const std::vector<validation::CaseResult>& cases, const std::string& dir) {
    FigureSet out;
    if (!gnuplot_available(out.note)) return out;
    const std::string term = terminal();
    const fs::path fig = fs::path(dir) / "figures";
    fs::create_directories(fig);
    for (const auto& c : cases) {
        std::vector<const validation::CaseRun*> runs;
        for (const auto& r : c.runs)
            if (r.analysed && !r.analysis.measured.t.empty()) runs.push_back(&r);
        if (runs.empty()) continue;
        const bool analytic = !runs.front()->analysis.analytic.empty();
        // the difference panel is scaled to the second-worst run so that one far-off run (clipped,
        // and said so) does not flatten the others
        std::vector<double> worst;
        for (const auto* r : runs) {
            double w = 0.0;
            std::istringstream in(curve_data(*r, runs.front()));
            std::string line;
            while (std::getline(in, line)) {
                if (line.empty() || line[0] == '#') continue;
                double a, b, c2, dd;
                std::istringstream ls(line);
                if (ls >> a >> b >> c2 >> dd && std::isfinite(dd)) w = std::max(w, std::abs(dd));
            }
            worst.push_back(w);
        }
        std::vector<double> sorted = worst;
        std::sort(sorted.rbegin(), sorted.rend());
        const bool clip = sorted.size() > 1 && sorted[1] > 0.0 && sorted[0] > 3.0 * sorted[1];
        std::ostringstream gp;
        gp << "set terminal " << term << "\nset output " << gnuplot_file(c.name + ".png") << "\n"
           << "set multiplot title " << gnuplot_string(c.name + ": " + c.scene.description) << "\n"
           << "set grid\nset key outside right top\nset lmargin 12\nset rmargin 24\nset autoscale xfix\n"
           << "set size 1,0.60\nset origin 0,0.37\nset ylabel " << gnuplot_string(runs.front()->analysis.quantity) << "\n"
           << "plot ";
        std::vector<std::string> lines;
        // each distinct reference curve once (rocking: rigid and penalty runs have different ones)
        std::vector<std::string> keys;
        for (const auto* r : runs) {
            if (r->analysis.analytic.empty()) continue;
            if (std::find(keys.begin(), keys.end(), r->analysis.analytic_key) != keys.end()) continue;
            keys.push_back(r->analysis.analytic_key);
            lines.push_back(gnuplot_file(c.name + "_" + r->variant.name + ".dat") + " u 1:3 w l lw 3 lc rgb '" +
                            (keys.size() == 1 ? "black" : "#777777") + "' dt " + std::to_string(keys.size() + 1) +
                            " t " + gnuplot_string(r->analysis.analytic_key));
        }
        for (size_t i = 0; i < runs.size(); ++i) {
            const std::string file = c.name + "_" + runs[i]->variant.name + ".dat";
            write_text_atomic((fig / file).string(), curve_data(*runs[i], runs.front()));
            lines.push_back(gnuplot_file(file) + " u 1:2 w l lw 1.5 lc rgb '" + variant_colour(runs[i]->variant.name) +
                            "' t " + gnuplot_string(runs[i]->variant.name));
        }
        for (size_t i = 0; i < lines.size(); ++i) gp << (i ? ", \\\n     " : "") << lines[i];
        std::string dlabel = analytic ? "run - analytic" : "run - " + runs.front()->variant.name;
        if (clip) {
            char b[64];
            std::snprintf(b, sizeof b, "set yrange [%g:%g]\n", -1.5 * sorted[1], 1.5 * sorted[1]);
            gp << "\n" << b;
            dlabel += " (clipped)";
        }
        gp << "\nset size 1,0.37\nset origin 0,0\nset xlabel 't (s)'\nset ylabel " << gnuplot_string(dlabel) << "\nplot ";
        for (size_t i = 0; i < runs.size(); ++i)
            gp << (i ? ", \\\n     " : "") << gnuplot_file(c.name + "_" + runs[i]->variant.name + ".dat")
               << " u 1:4 w l lw 1.5 lc rgb '" << variant_colour(runs[i]->variant.name) << "' t "
               << gnuplot_string(runs[i]->variant.name);
        gp << "\nunset multiplot\n";
        write_text_atomic((fig / (c.name + ".gp")).string(), gp.str());
        std::vector<std::string> images{"figures/" + c.name + ".png"};

        if (c.scene.reference->kind == "rolling") {
            // snapshots of the cube on the incline, one panel per variant
            write_text_atomic((fig / (c.name + "_fixed.dat")).string(), fixed_outline(c.scene));
            std::ostringstream sg;
            const int n = int(runs.size());
            std::string big = term;
            const auto at = big.find("760");
            if (at != std::string::npos) big.replace(at, 3, "1150");
            sg << "set terminal " << big << "\nset output " << gnuplot_file(c.name + "_snapshots.png") << "\n"
               << "set multiplot layout " << (n + 1) / 2 << "," << (n > 1 ? 2 : 1) << " title "
               << gnuplot_string(c.name + ": A every 0.25 s (x-z projection)") << "\n"
               << "set size ratio -1\nset xrange [-0.5:4.0]\nset yrange [-1.0:3.6]\nunset key\nset grid\n";
            for (const auto* r : runs) {
                const std::string file = c.name + "_" + r->variant.name + "_snap.dat";
                write_text_atomic((fig / file).string(), snapshot_data(c.scene, *r, 0.25, 16));
                sg << "set title " << gnuplot_string(r->variant.name) << "\nplot " << gnuplot_file(c.name + "_fixed.dat")
                   << " w filledcurves lc rgb '#cccccc', " << gnuplot_file(file) << " w l lw 1.2 lc rgb '#1f5fbf'\n";
            }
            sg << "unset multiplot\n";
            write_text_atomic((fig / (c.name + "_snapshots.gp")).string(), sg.str());
            images.push_back("figures/" + c.name + "_snapshots.png");
        }
        for (const auto& img : images) run_gnuplot_file(fig.string(), fs::path(img).stem().string(), out.note);
        for (const auto& img : images)
            if (fs::exists(fs::path(dir) / img)) out.images[c.name].push_back(img);
    }
    return out;
}

}  // namespace cairn::report
