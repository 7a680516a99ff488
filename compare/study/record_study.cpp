// the record study: backends' θ(t) against the rocking oracle under a record, and the chaos yardstick
#include "study/record_study.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>

#include "analytic/rocking_oracle_pulse.hpp"
#include "cases/case_util.hpp"
#include "error.hpp"
#include "metrics/signal.hpp"
#include "output/atomic_write.hpp"
#include "report/document.hpp"
#include "report/gnuplot.hpp"
#include "report/text.hpp"
#include "run/runner.hpp"
#include "run/stop.hpp"
#include "study/overturning_study.hpp"

namespace cairn::study {

double parting_time(const std::vector<double>& times, const std::vector<double>& a, const std::vector<double>& b,
                    double limit) {
    for (size_t i = 0; i < times.size() && i < a.size() && i < b.size(); ++i)
        if (!(std::abs(a[i] - b[i]) <= limit)) return times[i];   // NaN (a failed run) parts too
    return NAN;
}

namespace {

/// the oracle's θ at the times under the record scaled by `scale`, with restitution r
History oracle_history(const oracle::RockingOracle& o, const TimeSeries& rec, double scale, double r,
                       const std::vector<double>& times, const std::string& name) {
    oracle::RockingOptions opt;
    opt.restitution = r;
    opt.duration = times.back() + 1e-9;
    opt.output_times = times;
    const auto res = o.run(oracle::record_motion(rec, scale), opt);
    History h;
    h.method = name;
    h.theta = res.theta;
    h.max_theta = res.max_abs_theta;
    if (res.overturned) h.overturn_time = res.overturn_time;
    return h;
}

}  // namespace

RecordResult run_record_study(const RecordSetup& s, const RecordBackendMaker& make) {
    std::vector<Override> ov = s.overrides;
    ov.push_back({"run.output_interval", report::number_text(s.output_interval, 12)});
    const Scene scene = parse_scene(s.scene_text, s.scene_source, ov);
    if (!scene.ground_motion) throw Error(s.scene_source + ": the record study needs a [ground_motion]");
    const GroundMotion& gm = *scene.ground_motion;
    if (gm.components.size() != 1)
        throw Error(s.scene_source + ": the record study needs one ground motion record (along x)");
    const GroundComponent& record = gm.components.front();
    const double sign = record.direction.x();
    if (std::abs(std::abs(sign) - 1.0) > 1e-12)
        throw Error(s.scene_source + ": ground_motion.direction: the record study needs the motion along x");
    const auto rb = rocking_block_of(scene);
    const oracle::RockingOracle o(rb.b, rb.h, rb.g);
    RecordResult res;
    res.b = rb.b;
    res.h = rb.h;
    res.alpha = o.alpha();
    res.p = o.p();
    res.r = o.housner_restitution();
    res.duration = scene.run.duration;
    res.record = record.source;
    const long n = long(std::floor(res.duration / s.output_interval + 1e-9));
    if (n < 1 || n > 10000000L) throw Error("record study: between 1 and 1e7 compared samples are needed");
    for (long i = 0; i <= n; ++i) res.times.push_back(double(i) * s.output_interval);
    // the record in the oracle's frame: along +x, from the scene's start on
    TimeSeries rec = record.acceleration;
    for (auto& t : rec.time) t += gm.start;
    for (auto& v : rec.value) v *= sign;
    res.histories.push_back(oracle_history(o, rec, 1.0, res.r, res.times, "oracle"));
    res.histories.push_back(oracle_history(o, rec, 1.0, std::min(1.0, 1.01 * res.r), res.times, "oracle r+1%"));
    res.histories.push_back(oracle_history(o, rec, 1.01, res.r, res.times, "oracle record+1%"));
    std::vector<History> runs(s.backends.size());
    std::mutex print;
    run_pool(s.backends.size(), s.jobs, [&](size_t k) { return s.backends[k]; }, [&](size_t k) {
        History& h = runs[k];
        h.method = s.backends[k];
        try {
            auto backend = make(h.method);
            const RunResult r = run_scene(*backend, scene, RunOptions{});
            if (r.status != RunStatus::completed) h.status = r.status == RunStatus::unstable ? "unstable: " + r.message : "interrupted";
            const auto theta = cases::angle_series(r.samples, cases::free_index(scene, rb.block), Vec3::UnitY());
            for (double t : res.times) {
                const bool inside = !theta.t.empty() && t <= theta.t.back() + 1e-9;
                h.theta.push_back(inside ? metrics::interpolate(theta, t) : NAN);
            }
            for (size_t i = 0; i < theta.y.size(); ++i) {
                h.max_theta = std::max(h.max_theta, std::abs(theta.y[i]));
                if (std::isnan(h.overturn_time) && std::abs(theta.y[i]) >= M_PI / 3.0) h.overturn_time = theta.t[i];
            }
        } catch (const std::exception& e) {
            h.status = std::string(e.what()).substr(0, 300);
            h.theta.assign(res.times.size(), NAN);
        }
        std::lock_guard<std::mutex> lock(print);
        if (!s.quiet) std::cerr << "record: " << h.method << " " << h.status << "\n";
    }, s.exclusive);
    if (stop_requested()) throw Error("the record study was interrupted");
    for (auto& h : runs) res.histories.push_back(std::move(h));
    for (size_t i = 1; i < res.histories.size(); ++i)
        res.histories[i].parting = parting_time(res.times, res.histories[i].theta, res.histories[0].theta, 0.05 * res.alpha);
    return res;
}

namespace {

std::string fixed(double v, int digits) { return std::isfinite(v) ? report::fixed_text(v, digits) : "–"; }

}  // namespace

void write_record_study(const std::string& dir, const RecordResult& r) {
    namespace fs = std::filesystem;
    fs::create_directories(fs::path(dir) / "figures");
    std::ostringstream csv;
    csv << "t";
    for (const auto& h : r.histories) csv << "," << h.method;
    csv << "\n";
    for (size_t i = 0; i < r.times.size(); ++i) {
        csv << report::number_text(r.times[i], 10);
        for (const auto& h : r.histories) csv << "," << report::number_text(h.theta[i], 10);
        csv << "\n";
    }
    write_text_atomic((fs::path(dir) / "record.csv").string(), csv.str());
    std::string note;
    std::vector<std::string> figures;
    if (report::gnuplot_available(note)) {
        std::ostringstream gp;
        gp << "set terminal " << report::gnuplot_png_terminal() << " size 1200,600 font ',10'\n"
           << "set output 'record.png'\nset grid\nset key top left\nset datafile separator ','\n"
           << "set xlabel 'time (s)'\nset ylabel 'theta / alpha'\nset yrange [-3:3]\n"
           << "set title " << report::gnuplot_string("rocking under " + fs::path(r.record).filename().string() +
                                                     ": each backend against the oracle")
           << " noenhanced\nplot ";
        const char* colours[] = {"black", "#7f7f7f", "#17becf", "#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#8c564b"};
        for (size_t k = 0; k < r.histories.size(); ++k)
            gp << (k ? ", " : "") << report::gnuplot_file("../record.csv") << " every ::1 using 1:($" << k + 2 << "/"
               << report::number_text(r.alpha, 12) << ") with lines lw " << (k == 0 ? 3 : 1)
               << (k == 1 || k == 2 ? " dt 2" : "") << " lc rgb '" << colours[k % 8] << "' title "
               << report::gnuplot_string(r.histories[k].method) << " noenhanced";
        gp << "\n";
        if (report::run_gnuplot((fs::path(dir) / "figures").string(), "record", gp.str(), note))
            figures.push_back("figures/record.png");
    }
    report::Document doc;
    doc.title = "cairn: record study";
    doc.heading(2, "Rocking under a record");
    doc.paragraph("Record: " + r.record + ", " + fixed(r.duration, 2) + " s. Block " + fixed(2 * r.b, 3) + " m wide and " +
                  fixed(2 * r.h, 3) + " m high: alpha = " + fixed(r.alpha, 5) + " rad, p = " + fixed(r.p, 4) +
                  " 1/s, Housner's r = " + fixed(r.r, 5) + ". Each history parts from the oracle's when |theta - " +
                  "theta_oracle| first exceeds 5 % of alpha (" + fixed(0.05 * r.alpha, 5) + " rad). The yardstick: " +
                  "the oracle itself with r or the record 1 % larger; a backend that parts later than the yardstick " +
                  "is as close as the problem's own sensitivity allows.");
    for (const auto& f : figures) doc.image(f, "theta / alpha against time");
    if (!note.empty()) doc.paragraph("Figures: " + note);
    report::Table t;
    t.header = {"history", "parts from the oracle at (s)", "largest |theta| / alpha", "overturned at (s)", "status"};
    for (const auto& h : r.histories)
        t.rows.push_back({h.method, h.method == "oracle" ? "–" : std::isfinite(h.parting) ? fixed(h.parting, 3) : "never",
                          fixed(h.max_theta / r.alpha, 3), std::isfinite(h.overturn_time) ? fixed(h.overturn_time, 3) : "no",
                          h.status});
    doc.table(t);
    write_text_atomic((fs::path(dir) / "record.md").string(), report::to_markdown(doc));
    write_text_atomic((fs::path(dir) / "record.html").string(), report::to_html(doc));
}

}  // namespace cairn::study
