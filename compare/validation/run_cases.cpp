#include "validation/run_cases.hpp"

#include <cstdio>
#include <filesystem>
#include <mutex>

#include "cases/case_kind.hpp"
#include "error.hpp"
#include "metrics/diff.hpp"
#include "scene/scene_io.hpp"

namespace fs = std::filesystem;

namespace cairn::validation {

const char* outcome_text(Outcome o) {
    switch (o) {
        case Outcome::completed: return "completed";
        case Outcome::unstable: return "unstable";
        case Outcome::interrupted: return "interrupted";
        case Outcome::refused: return "cannot represent";
        case Outcome::input_error:
        case Outcome::failed: return "failed";
    }
    return "?";
}

namespace {

/// the run's scene: the case's scene with the variant's block model
Scene variant_scene(const Scene& case_scene, const Variant& v) {
    Scene scene = case_scene;
    apply_model(scene, v.model);
    return scene;
}

/// a finished run into its CaseRun, analysed against its case
void take_result(CaseRun& run, const Scene& scene, JobResult& r) {
    run.outcome = r.outcome == Outcome::input_error ? Outcome::failed : r.outcome;
    run.message = r.message;
    run.samples = std::move(r.result.samples);
    run.wall_seconds = r.result.wall_seconds;
    run.dt = r.result.dt;
    run.steps = r.result.steps;
    run.energy_gain = r.result.energy_gain;
    run.energy_created = energy_created_text(r.result);
    run.warnings = r.result.warnings;
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
    const std::string probe_name = probe >= 0 ? c.scene.probes[size_t(probe)].name : "";
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
                                            probe_name + ", same times"));
            if (shift != 0.0)
                r.diffs.push_back(metrics::info("probe path RMS" + vs + ", aligned", "m",
                                                metrics::probe_path_rms(r.samples, base->samples, probe, shift), NAN,
                                                probe_name + ", time shifted by the first-event shift"));
        }
    }
}

}  // namespace

void run_plan(RunPlan& plan, const std::vector<BackendInfo>& backends) {
    struct Where {
        size_t c, r;
    };
    std::vector<Where> where;
    std::vector<Scene> scenes;   // per run, the variant's scene
    std::vector<RunSpec> jobs;
    const std::string named = plan.final_dir.empty() ? plan.out_dir : plan.final_dir;
    for (size_t c = 0; c < plan.cases.size(); ++c)
        for (size_t r = 0; r < plan.cases[c].runs.size(); ++r) {
            CaseRun& run = plan.cases[c].runs[r];
            const fs::path sub = fs::path("runs") / plan.cases[c].name / run.variant.name;
            run.out_dir = (fs::path(named) / sub).string();
            where.push_back({c, r});
            scenes.push_back(variant_scene(plan.cases[c].scene, run.variant));
            RunSpec job;
            job.backend = run.variant.backend;
            job.options.contact_mode = run.variant.contact_mode;
            job.out_dir = (fs::path(plan.out_dir) / sub).string();   // the same files as `cairn run`
            job.request.scene_path = plan.scene_paths[c];
            job.request.overrides = plan.overrides;
            job.request.model_override = run.variant.model;
            job.request.options = job.options;
            job.label = plan.cases[c].name + " " + run.variant.name;
            jobs.push_back(std::move(job));
        }
    for (size_t j = 0; j < jobs.size(); ++j) jobs[j].scene = &scenes[j];
    JobsOptions options;
    options.jobs = plan.jobs;
    options.quiet = true;   // validate's own line per run below
    options.progress = plan.progress;
    std::mutex print;
    size_t done = 0;
    run_jobs(jobs, backends, options, [&](size_t j, JobResult& r) {
        CaseResult& c = plan.cases[where[j].c];
        CaseRun& run = c.runs[where[j].r];
        take_result(run, scenes[j], r);
        if (plan.quiet) return;
        std::lock_guard<std::mutex> lock(print);
        std::fprintf(stderr, "[%zu/%zu] %s %s: %s (%.2f s)\n", ++done, jobs.size(), c.name.c_str(),
                     run.variant.name.c_str(), outcome_text(run.outcome), run.wall_seconds);
    });
    for (auto& c : plan.cases) diff_runs(c);
}

}  // namespace cairn::validation
