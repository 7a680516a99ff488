#include "validation/run_cases.hpp"

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>

#include "cases/case_kind.hpp"
#include "error.hpp"
#include "metrics/diff.hpp"
#include "output/atomic_write.hpp"
#include "output/run_record.hpp"
#include "output/trajectory_csv.hpp"
#include "run/runner.hpp"
#include "run/stop.hpp"

namespace fs = std::filesystem;

namespace cairn::validation {

const char* to_string(Outcome o) {
    switch (o) {
        case Outcome::completed: return "completed";
        case Outcome::unstable: return "unstable";
        case Outcome::refused: return "cannot represent";
        case Outcome::failed: return "failed";
    }
    return "?";
}

namespace {

/// one run: build, step, write its files, analyse; never throws
void execute(CaseRun& run, const fs::path& dir, const Scene& case_scene, const std::string& scene_path,
             const RunPlan& plan, const BackendFactory& make, const ProgressFn& progress) {
    Scene scene = case_scene;
    const BlockModel model = run.variant.model == "deformable" ? BlockModel::deformable : BlockModel::rigid;
    for (auto& b : scene.blocks)
        if (!b.fixed) b.model = model;
    RunRequest request;
    request.scene_path = scene_path;
    request.overrides = plan.overrides;
    request.model_override = run.variant.model;
    request.options.contact_mode = run.variant.contact_mode;
    std::unique_ptr<Backend> backend;
    RunResult result;
    // the same files as `cairn run`, through the same streaming writer; the samples are kept too,
    // for the analysis
    CollectingSink collect;
    TrajectoryCsvFile csv((dir / "trajectory.csv").string());
    TeeSink sink({&collect, &csv});
    try {
        backend = make(run.variant.backend);
        fs::create_directories(dir);
        result = run_scene(*backend, scene, request.options, sink, progress);
    } catch (const Error& e) {
        std::error_code ec;
        fs::remove(dir, ec);   // refused before the first sample: the directory is still empty
        run.outcome = Outcome::refused;
        run.message = e.what();
        return;
    } catch (const std::exception& e) {
        run.outcome = Outcome::failed;
        run.message = std::string("unexpected failure: ") + e.what();
        return;
    }
    run.outcome = result.status == RunStatus::completed ? Outcome::completed : Outcome::unstable;
    run.message = result.message;
    run.samples = std::move(collect.samples);
    run.wall_seconds = result.wall_seconds;
    run.dt = result.dt;
    run.steps = result.steps;
    try {
        // a partial trajectory keeps its own name
        if (run.outcome != Outcome::completed) fs::rename(dir / "trajectory.csv", dir / "trajectory.partial.csv");
        write_text_atomic((dir / "run.json").string(), run_record_text(scene, *backend, result, request));
    } catch (const std::exception& e) {
        run.outcome = Outcome::failed;
        run.message = std::string("cannot write outputs: ") + e.what();
    }
    try {
        if (run.samples.size() >= 3 && scene.reference) {   // a scene without a reference has nothing to judge
            run.analysis = cases::analyse_case(scene, run.samples, contact_kind(run.variant, scene));
            run.analysed = true;
        }
    } catch (const std::exception& e) {
        run.message += (run.message.empty() ? "" : "; ") + std::string("analysis failed: ") + e.what();
    }
}

/// info metrics of each analysed run against the case's first analysed run
void diff_runs(CaseResult& c) {
    const CaseRun* base = nullptr;
    for (const auto& r : c.runs)
        if (r.analysed) { base = &r; break; }
    if (!base) return;
    int probe = -1;
    for (size_t i = 0; i < c.scene.probes.size(); ++i)
        if (c.scene.probes[i].name == "node10") probe = int(i);
    if (probe < 0 && !c.scene.probes.empty()) probe = 0;
    for (auto& r : c.runs) {
        if (!r.analysed || &r == base) continue;
        double shift = 0.0;
        const std::string vs = " vs " + base->variant.name;
        if (r.analysis.has_event && base->analysis.has_event) {
            shift = r.analysis.event_time - base->analysis.event_time;
            r.diffs.push_back(metrics::info("first-event time shift" + vs, "s", shift, NAN,
                                            "event: " + cases::case_kind(c.scene.reference->kind, c.scene.source).event_label()));
        }
        if (probe >= 0) {
            r.diffs.push_back(metrics::info("probe path RMS" + vs, "m",
                                            metrics::probe_path_rms(r.samples, base->samples, probe, 0.0), NAN,
                                            "node10, same times"));
            if (shift != 0.0)
                r.diffs.push_back(metrics::info("probe path RMS" + vs + ", aligned", "m",
                                                metrics::probe_path_rms(r.samples, base->samples, probe, shift), NAN,
                                                "node10, time shifted by the first-event shift"));
        }
    }
}

}  // namespace

void run_plan(RunPlan& plan, const BackendFactory& make) {
    struct Job {
        size_t c, r;
        fs::path dir;   ///< where the run's files are written
    };
    std::vector<Job> jobs;
    const std::string named = plan.final_dir.empty() ? plan.out_dir : plan.final_dir;
    for (size_t c = 0; c < plan.cases.size(); ++c)
        for (size_t r = 0; r < plan.cases[c].runs.size(); ++r) {
            CaseRun& run = plan.cases[c].runs[r];
            const fs::path sub = fs::path("runs") / plan.cases[c].name / run.variant.name;
            run.out_dir = (fs::path(named) / sub).string();
            jobs.push_back({c, r, fs::path(plan.out_dir) / sub});
        }
    std::atomic<size_t> next{0};
    std::atomic<size_t> done{0};
    std::mutex print;
    std::map<std::string, std::mutex> serial;
    for (const auto& b : plan.serial_backends) serial[b];
    auto worker = [&] {
        for (size_t j; !stop_requested() && (j = next++) < jobs.size();) {
            CaseResult& c = plan.cases[jobs[j].c];
            CaseRun& run = c.runs[jobs[j].r];
            ProgressFn progress;
            if (plan.progress) progress = [&plan, j](double f) { plan.progress(j, f); };
            auto it = serial.find(run.variant.backend);
            if (it != serial.end()) {
                std::lock_guard<std::mutex> lock(it->second);
                execute(run, jobs[j].dir, c.scene, plan.scene_paths[jobs[j].c], plan, make, progress);
            } else {
                execute(run, jobs[j].dir, c.scene, plan.scene_paths[jobs[j].c], plan, make, progress);
            }
            if (plan.progress) plan.progress(j, 1.0);
            size_t n = ++done;
            if (!plan.quiet) {
                std::lock_guard<std::mutex> lock(print);
                std::fprintf(stderr, "[%zu/%zu] %s %s: %s (%.2f s)\n", n, jobs.size(), c.name.c_str(),
                             run.variant.name.c_str(), to_string(run.outcome), run.wall_seconds);
            }
        }
    };
    const int n = std::max(1, std::min<int>(plan.jobs, int(jobs.size())));
    std::vector<std::thread> pool;
    for (int i = 0; i < n; ++i) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    for (auto& c : plan.cases) diff_runs(c);
}

}  // namespace cairn::validation
