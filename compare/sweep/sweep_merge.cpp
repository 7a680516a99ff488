#include "sweep/sweep_merge.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "error.hpp"
#include "output/atomic_write.hpp"
#include "report/text.hpp"
#include "sweep/fragility_report.hpp"
#include "sweep/sweep_result.hpp"

namespace fs = std::filesystem;

namespace cairn::sweep {

namespace {

/// a number as exact text (17 significant digits): the same double gives the same text
std::string exact(double v) { return report::number_text(v, 17); }

}  // namespace

std::string result_path(const std::string& dir, const std::string& id) {
    return (fs::path(dir) / "results" / (id + ".json")).string();
}

std::string run_dir(const std::string& dir, const std::string& id) { return (fs::path(dir) / "runs" / id).string(); }

MergeSummary merge_sweep(const Sweep& sweep, const std::string& dir) {
    MergeSummary m;
    m.runs = sweep.runs.size();
    std::vector<SweepResult> results;
    for (const auto& run : sweep.runs) {
        const std::string p = result_path(dir, run.id);
        if (!fs::exists(p)) {
            m.missing.push_back(run.id);
            continue;
        }
        results.push_back(read_result(p));
        if (results.back().id != run.id) throw Error(p + ": holds the result of run " + results.back().id);
    }
    if (!m.missing.empty()) return m;

    // the table: what the runs are and what they gave, in expansion order, numbers exact
    std::ostringstream t, w;
    t << "id,scene,backend,record,intensity_g,scale";
    for (const auto& a : sweep.plan.axes) t << "," << report::csv_field(a.key);
    t << ",repeat,status,overturned,peak_rotation_rad,final_rotation_rad,residual_displacement_m,duration_s,steps,dt_s,"
         "message\n";
    w << "id,backend,wall_s\n";
    for (size_t i = 0; i < sweep.runs.size(); ++i) {
        const auto& run = sweep.runs[i];
        const auto& r = results[i];
        t << run.id << "," << report::csv_field(run.scene_name) << "," << run.backend << "," << run.record << ","
          << exact(run.intensity) << "," << exact(run.scale);
        for (const auto& v : run.axis_values) t << "," << report::csv_field(v);
        t << "," << run.repeat << "," << r.status << "," << (r.overturned ? 1 : 0) << "," << exact(r.peak_rotation)
          << "," << exact(r.final_rotation) << "," << exact(r.residual_displacement) << "," << exact(r.duration) << ","
          << r.steps << "," << exact(r.dt) << "," << report::csv_field(r.message) << "\n";
        w << run.id << "," << run.backend << "," << exact(r.wall_seconds) << "\n";
    }
    write_text_atomic((fs::path(dir) / "runs.csv").string(), t.str());
    write_text_atomic((fs::path(dir) / "timing.csv").string(), w.str());
    if (sweep.plan.kind == "fragility") m.note = write_fragility_report(sweep, results, dir);
    return m;
}

}  // namespace cairn::sweep
