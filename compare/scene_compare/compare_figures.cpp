#include "scene_compare/compare_figures.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "scene_compare/block_diff.hpp"
#include "output/atomic_write.hpp"
#include "report/gnuplot.hpp"
#include "report/palette.hpp"

namespace fs = std::filesystem;

namespace cairn::scene_compare {

std::string history_csv(const BlockHistory& h) {
    std::ostringstream o;
    o.precision(10);
    o << "t [s],x [m],y [m],z [m],rotation angle [rad],speed [m/s]\n";
    for (size_t i = 0; i < h.t.size(); ++i)
        o << h.t[i] << "," << h.x[i] << "," << h.y[i] << "," << h.z[i] << "," << h.angle[i] << "," << h.speed[i] << "\n";
    return o.str();
}

std::string difference_csv(const BlockHistory& run, const BlockHistory& base) {
    std::ostringstream o;
    o.precision(10);
    o << "t [s],distance to baseline [m],rotation angle difference [rad],speed difference [m/s]\n";
    const DifferenceSeries d = differences(run, base);
    for (size_t i = 0; i < d.t.size(); ++i) o << d.t[i] << "," << d.distance[i] << "," << d.angle[i] << "," << d.speed[i] << "\n";
    return o.str();
}

std::string energy_csv(const std::vector<Sample>& samples) {
    std::ostringstream o;
    o.precision(10);
    o << "t [s],kinetic [J],potential [J],contact [J],strain [J],dissipated [J],work by loads [J],"
         "balance error [J],contact points\n";
    const double e0 = samples.empty() ? 0.0 : samples.front().energy.total();
    for (const auto& s : samples) {
        const Energies& e = s.energy;
        o << s.t << "," << e.kinetic << "," << e.potential << "," << e.contact << "," << e.strain << ","
          << e.dissipated << "," << e.external << "," << e.total() - e0 << "," << s.contacts << "\n";
    }
    return o.str();
}

std::string history_file(const std::string& variant, int free_block) {
    return "data/" + variant + "_block" + std::to_string(free_block + 1) + ".csv";
}
std::string difference_file(const std::string& variant, int free_block) {
    return "data/" + variant + "_block" + std::to_string(free_block + 1) + "_difference.csv";
}
std::string energy_file(const std::string& variant) { return "data/" + variant + "_energy.csv"; }

void write_data(const std::vector<VariantHistories>& variants, int base, const std::vector<size_t>& shown,
                const std::string& dir) {
    fs::create_directories(fs::path(dir) / "data");
    for (size_t v = 0; v < variants.size(); ++v) {
        const std::string& name = variants[v].run->variant.name;
        write_text_atomic((fs::path(dir) / energy_file(name)).string(), energy_csv(variants[v].run->samples));
        for (size_t b : shown) {
            if (b >= variants[v].blocks.size()) continue;
            write_text_atomic((fs::path(dir) / history_file(name, int(b))).string(), history_csv(variants[v].blocks[b]));
            if (base >= 0 && int(v) != base && b < variants[size_t(base)].blocks.size())
                write_text_atomic((fs::path(dir) / difference_file(name, int(b))).string(),
                                  difference_csv(variants[v].blocks[b], variants[size_t(base)].blocks[b]));
        }
    }
}

namespace {

/// text as a gnuplot string: scene and block names are untrusted
std::string q(const std::string& s) { return report::gnuplot_string(s); }

std::string header(const std::string& png, int height) {
    std::ostringstream o;
    o << "set terminal " << report::gnuplot_png_terminal() << " noenhanced size 1000," << height
      << " font 'sans,10'\nset output " << q(png) << "\nset datafile separator ','\nset grid\n"
      << "set lmargin 12\nset rmargin 22\nset autoscale xfix\n";
    return o.str();
}

/// one panel: column `col` of each variant's file
std::string panel(const std::vector<VariantHistories>& variants, const std::vector<std::string>& files,
                  const std::vector<int>& which, int col, const std::string& ylabel, bool key) {
    std::ostringstream o;
    o << "set ylabel " << q(ylabel) << "\n" << (key ? "set key outside right top\n" : "unset key\n") << "plot ";
    for (size_t i = 0; i < which.size(); ++i) {
        const std::string& name = variants[size_t(which[i])].run->variant.name;
        o << (i ? ", \\\n     " : "") << q("../" + files[i]) << " skip 1 u 1:" << col << " w l lw 1.5 lc rgb '"
          << report::variant_colour(name) << "' t " << q(name);
    }
    return o.str() + "\n";
}

}  // namespace

std::vector<std::string> draw_figures(const std::vector<VariantHistories>& variants, int base,
                                      const std::vector<std::string>& block_names, const std::vector<size_t>& shown,
                                      const std::string& dir, std::string& note) {
    std::vector<std::string> out;
    if (variants.empty() || !report::gnuplot_available(note)) return out;
    const fs::path fig = fs::path(dir) / "figures";
    fs::create_directories(fig);
    std::vector<int> all;
    for (size_t v = 0; v < variants.size(); ++v) all.push_back(int(v));
    for (size_t shown_block : shown) {
        if (shown_block >= block_names.size()) continue;
        const int b = int(shown_block);
        const std::string stem = "block" + std::to_string(b + 1);
        std::vector<std::string> files;
        std::vector<int> which;
        for (int v : all)
            if (size_t(b) < variants[size_t(v)].blocks.size()) {
                files.push_back(history_file(variants[size_t(v)].run->variant.name, b));
                which.push_back(v);
            }
        std::ostringstream gp;
        gp << header(stem + ".png", 1250) << "set multiplot layout 5,1 title " << q(block_names[size_t(b)] + ": histories")
           << "\n";
        gp << panel(variants, files, which, 2, "x (m)", true) << panel(variants, files, which, 3, "y (m)", false)
           << panel(variants, files, which, 4, "z (m)", false)
           << panel(variants, files, which, 5, "rotation angle (rad)", false) << "set xlabel 't (s)'\n"
           << panel(variants, files, which, 6, "speed (m/s)", false) << "unset multiplot\n";
        if (report::run_gnuplot(fig.string(), stem, gp.str(), note)) out.push_back("figures/" + stem + ".png");
        if (base < 0 || which.size() < 2) continue;
        files.clear();
        std::vector<int> others;
        for (int v : which)
            if (v != base) {
                files.push_back(difference_file(variants[size_t(v)].run->variant.name, b));
                others.push_back(v);
            }
        const std::string bname = variants[size_t(base)].run->variant.name;
        std::ostringstream dg;
        dg << header(stem + "_diff.png", 900) << "set multiplot layout 3,1 title "
           << q(block_names[size_t(b)] + ": difference to " + bname) << "\n"
           << panel(variants, files, others, 2, "distance to " + bname + " (m)", true)
           << panel(variants, files, others, 3, "rotation minus " + bname + " (rad)", false) << "set xlabel 't (s)'\n"
           << panel(variants, files, others, 4, "speed minus " + bname + " (m/s)", false) << "unset multiplot\n";
        if (report::run_gnuplot(fig.string(), stem + "_diff", dg.str(), note))
            out.push_back("figures/" + stem + "_diff.png");
    }
    std::vector<std::string> efiles;
    for (int v : all) efiles.push_back(energy_file(variants[size_t(v)].run->variant.name));
    std::ostringstream eg;
    eg << header("energy.png", 900) << "set multiplot layout 3,1 title 'energy and contacts'\n"
       << panel(variants, efiles, all, 2, "kinetic energy (J)", true)
       << panel(variants, efiles, all, 8, "balance error (J)", false) << "set xlabel 't (s)'\n"
       << panel(variants, efiles, all, 9, "contact points (count)", false) << "unset multiplot\n";
    if (report::run_gnuplot(fig.string(), "energy", eg.str(), note)) out.push_back("figures/energy.png");
    // keep only images gnuplot actually produced
    out.erase(std::remove_if(out.begin(), out.end(), [&](const std::string& p) { return !fs::exists(fs::path(dir) / p); }),
              out.end());
    return out;
}

}  // namespace cairn::scene_compare
