#include "bench/scale_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench/bench_report.hpp"
#include "bench/scale_bench.hpp"
#include "bench/scale_large.hpp"
#include "bench/scale_pushover.hpp"
#include "output/atomic_write.hpp"
#include "report/gnuplot.hpp"

namespace fs = std::filesystem;

namespace cairn::bench {

namespace {

std::string fmt(const char* f, double v) { return number_format(f, v); }

std::string slurp(const fs::path& p) { return read_whole(p.string()); }

// figures/scale_cost.png: cost per simulated second against bricks, log-log, one line per backend
std::string cost_figure(const std::string& dir, const std::vector<ScaleRow>& rows,
                        const std::vector<std::string>& backends, std::string& note) {
    if (!report::gnuplot_available(note)) return "";
    const fs::path fig = fs::path(dir) / "figures";
    fs::create_directories(fig);
    std::ostringstream dat;
    for (const auto& b : backends) {
        dat << "# " << b << ": bricks, wall s per simulated s\n";
        for (const auto& r : rows)
            if (r.backend == b && r.status.rfind("completed", 0) == 0 && r.cost > 0.0) dat << r.blocks << " " << r.cost << "\n";
        dat << "\n\n";
    }
    write_text_atomic((fig / "scale_cost.dat").string(), dat.str());
    std::ostringstream gp;
    gp << "set terminal " << report::gnuplot_png_terminal() << " size 900,620 font ',11'\n"
       << "set output " << report::gnuplot_file("scale_cost.png") << "\nset logscale xy\nset grid\nset key left top\n"
       << "set title 'cost per simulated second against the number of bricks (static-settlement accuracy 1 %)'\n"
       << "set xlabel 'bricks'\nset ylabel 'wall seconds per simulated second'\nplot ";
    for (size_t i = 0; i < backends.size(); ++i)
        gp << (i ? ", " : "") << report::gnuplot_file("scale_cost.dat") << " index " << i
           << " using 1:2 with linespoints lw 2 pt 7 title " << report::gnuplot_string(backends[i]);
    gp << "\n";
    return report::run_gnuplot(fig.string(), "scale_cost", gp.str(), note) ? "figures/scale_cost.png" : "";
}

// the large model's run (cairn bench scale --large)
void add_large_rows(report::Document& d, const LargeRun& r) {
    d.heading(3, "A building-scale model under El Centro (cairn bench scale --large)");
    d.paragraph("A four-wall brick tower (cairn make tower bricks, 0.24 × 0.12 × 0.07 m, kn = ks = 1e9 N/m³, μ = 0.7, "
                "ζ = 0.1) shaken along x by the shipped El Centro 1940 NS record from its start, on dem (overlap scheme, "
                "one sub-contact per hitting face, dt auto), samples dropped. The whole record's time is this run's "
                "wall seconds per simulated second times " + fmt("%g", kLargeRecordSeconds) + " s.");
    report::Table t{{"bricks", "simulated", "dt", "steps", "wall", "per simulated s", "15 s of record", "peak memory",
                     "sub-contacts", "ns per sub-contact and step", "energy balance", "status"}, {}};
    t.rows.push_back({std::to_string(r.blocks), fmt("%g s", r.duration), fmt("%.3g s", r.dt), std::to_string(r.steps),
                      fmt("%.0f s", r.wall_seconds), fmt("%.0f s", r.cost()), fmt("%.2f h", r.cost() * kLargeRecordSeconds / 3600.0),
                      fmt("%.0f MB", r.peak_mb), fmt("%.0f", r.contacts), fmt("%.0f", r.ns_per_contact()),
                      (r.energy_closed ? "closed, " : "drifted, ") + fmt("%.2g", r.max_balance_error), r.status.substr(0, 100)});
    d.table(t);
}

// the second accuracy measure (scale_pushover.csv)
void add_pushover_rows(report::Document& d, const std::vector<PushoverPoint>& pts) {
    d.heading(3, "Accuracy 2: the pushover multiplier of a free-standing wall");
    d.paragraph("scenarios/structures/wall_pushover: 18 bricks (4 courses of 0.4 × 0.2 × 0.2 m with half-brick closers, "
                "t/H = 0.25) under an out-of-plane acceleration ramped over 36 s; the a/g at which the top turns 0.05 rad "
                "against the rigid wall's (t/H plus the ramp's lag), within 2 %. Each backend's settings cheapest first, "
                "until one reaches it: dem at run.dt_safety 0.4, 0.2, 0.1 of its critical step (the scene's contact), the "
                "engines in their rigid contact at dt 1e-3, 3e-4, 1e-4 s (ODE's exact dWorldStep).");
    report::Table t{{"backend", "setting", "dt", "a/g", "reference", "error", "s per simulated s", "status"}, {}};
    for (const auto& p : pts)
        t.rows.push_back({p.backend, p.setting, fmt("%.3g s", p.dt), fmt("%.4f", p.multiplier), fmt("%.4f", p.reference),
                          fmt("%+.2f %%", 100.0 * p.error), fmt("%.3g", p.cost), p.status.substr(0, 100)});
    d.table(t);
    std::vector<std::string> best;
    std::vector<std::string> seen;
    for (const auto& p : pts) {
        if (std::find(seen.begin(), seen.end(), p.backend) != seen.end()) continue;
        seen.push_back(p.backend);
        const auto* c = cheapest_reaching(pts, p.backend, 0.02);
        best.push_back(p.backend + ": " + (c ? fmt("%.3g", c->cost) + " wall s per simulated s (" + c->setting + ")"
                                             : std::string("no setting tried reaches 2 %")));
    }
    d.bullets(best);
}

}  // namespace

void add_scale_section(report::Document& d, const std::string& dir, std::string& note) {
    const fs::path root = dir;
    const bool large = fs::exists(root / "scale_large.csv");
    if (!fs::exists(root / "scale.csv")) {
        if (large) d.heading(2, "Cost against model size at equal accuracy (cairn bench scale)");
        if (large) add_large_rows(d, parse_large_csv(slurp(root / "scale_large.csv")));
        return;
    }
    const auto rows = parse_scale_csv(slurp(root / "scale.csv"));
    const auto acc = fs::exists(root / "scale_accuracy.csv") ? parse_scale_accuracy_csv(slurp(root / "scale_accuracy.csv"))
                                                             : std::vector<ScaleAccuracy>{};
    std::vector<std::string> backends;
    for (const auto& r : rows)
        if (std::find(backends.begin(), backends.end(), r.backend) == backends.end()) backends.push_back(r.backend);
    d.heading(2, "Cost against model size at equal accuracy (cairn bench scale)");
    d.paragraph("Running-bond walls of 0.4 × 0.2 × 0.2 m bricks at kn = ks = 3e9 N/m³, the reference engines with "
                "springs matched to the joints, dem with its overlap scheme at one sub-contact per hitting face "
                "(the exact integral of kn·d; the paper's 0.1 m grid settles 12 % short per brick-on-brick joint). Accuracy first: a 10 × 10 wall released touching settles under "
                "gravity with mass damping; its top course must sink by the sum of the joints' compressions, "
                "ρ g h C(C + 1)/(2 kn), within 1 %. Each backend's time step is the largest of 1e-3, 3e-4, 1e-4 and 3e-5 s that "
                "does (a backend that misses at every dt is timed at its largest completed one and its rows say so). Cost: the walls of each size placed at their static penetrations, a few steps timed one "
                "backend after the other on the same machine; wall seconds per simulated second = time per step / "
                "dt. Peak memory is the process's resident peak while building and stepping (it includes the "
                "program itself). MuJoCo has no row: its backend refuses the 300-brick wall already (831 "
                "touching pairs need about 20 000 constraint rows; MuJoCo 2.2.2's constraint storage grows with "
                "the square of njmax and stops near 10 000).");
    report::Table ta{{"backend", "dt", "settlement", "closed form", "error", "status"}, {}};
    for (const auto& a : acc)
        ta.rows.push_back({a.backend, fmt("%g s", a.dt), fmt("%.4g m", a.settlement), fmt("%.4g m", a.expected),
                           fmt("%+.2f %%", 100.0 * a.error), a.status.substr(0, 100)});
    if (!ta.rows.empty()) d.table(ta);
    report::Table t{{"backend", "bricks", "dt", "s per step", "s per simulated s", "peak memory", "status"}, {}};
    for (const auto& r : rows)
        t.rows.push_back({r.backend, std::to_string(r.blocks), fmt("%g s", r.dt), fmt("%.3g", r.step_seconds),
                          fmt("%.3g", r.cost), fmt("%.0f MB", r.peak_mb), r.status.substr(0, 100)});
    d.table(t);
    std::vector<std::string> fits;
    for (const auto& b : backends) {
        std::vector<double> n, cost, mem;
        for (const auto& r : rows)
            if (r.backend == b && r.status.rfind("completed", 0) == 0) n.push_back(r.blocks), cost.push_back(r.cost), mem.push_back(r.peak_mb);
        fits.push_back(b + ": cost ∝ N^" + fmt("%.2f", fitted_exponent(n, cost)) + ", peak memory ∝ N^" +
                       fmt("%.2f", fitted_exponent(n, mem)) + " (least squares in log-log over the completed sizes)");
    }
    d.bullets(fits);
    const std::string img = cost_figure(dir, rows, backends, note);
    if (!img.empty()) d.image(img, "wall seconds per simulated second against bricks, per backend");
    if (fs::exists(root / "scale_pushover.csv")) add_pushover_rows(d, parse_pushover_csv(slurp(root / "scale_pushover.csv")));
    if (large) add_large_rows(d, parse_large_csv(slurp(root / "scale_large.csv")));
}

}  // namespace cairn::bench
