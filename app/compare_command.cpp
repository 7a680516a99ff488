// `cairn compare`: one scene on every backend variant that takes it, compared with each other (and
// with the analytic reference when the scene has one) in report.md and index.html
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>


#include "backend_option.hpp"
#include "commands.hpp"
#include "error.hpp"
#include "output/atomic_write.hpp"
#include "output/staged_dir.hpp"
#include "progress_line.hpp"
#include "registry.hpp"
#include "report/document.hpp"
#include "run/core_pool.hpp"
#include "run/stop.hpp"
#include "scene/scene_io.hpp"
#include "scene_compare/compare_report.hpp"
#include "scene_compare/variants.hpp"
#include "scenes.hpp"
#include "suggest.hpp"
#include "validation/run_cases.hpp"

namespace fs = std::filesystem;

namespace cairn {

namespace {

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + v[i];
    return s;
}

/// the command that reproduces this comparison
std::string command_line(const CompareOptions& o, const std::string& out_dir) {
    std::string c = "cairn compare " + o.scene + " --out " + out_dir;
    if (!o.backends.empty()) c += " --backends " + join(o.backends);
    if (o.model != "both") c += " --model " + o.model;
    if (!o.baseline.empty()) c += " --baseline " + o.baseline;
    for (const auto& s : o.overrides) c += " --set " + s;
    return c;
}

}  // namespace

int compare_command(const CompareOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    validation::RunPlan plan;
    validation::CaseResult c;
    std::string out_dir = options.out_dir;
    std::vector<std::string> backends;
    try {
        backends = chosen_backends(options.backends);
        const std::string path = resolve_scene(options.scene);
        std::vector<Override> overrides;
        for (const auto& s : options.overrides) overrides.push_back(parse_override(s));
        // the name is part of paths and figure scripts: only letters, digits, '-', '_' and '.' of it
        c.name = fs::path(path).stem().string();
        for (auto& ch : c.name)
            if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '_' && ch != '.') ch = '_';
        if (c.name.empty() || c.name[0] == '.') c.name = "scene" + c.name;
        c.scene = load_scene(path, overrides);
        check_backend_tables(c.scene, path);
        for (const auto& v : scene_compare::compare_variants(c.scene, backend_infos(backends), options.model)) {
            validation::CaseRun r;
            r.case_name = c.name;
            r.variant = v;
            c.runs.push_back(std::move(r));
        }
        if (c.runs.empty()) throw Error("--model " + options.model + ": no variant of the chosen backends has that block model");
        if (out_dir.empty()) out_dir = (fs::path("out") / "compare" / c.name).string();
        plan.scene_paths.push_back(path);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    // runs at a time: the cores, at most (the run layer shares them: runs × threads ≤ cores)
    const int cores = machine_cores();
    int jobs = options.jobs > 0 ? options.jobs : cores;
    if (jobs > cores) {
        std::cerr << "note: --jobs " << jobs << " lowered to the " << cores << " cores of this machine\n";
        jobs = cores;
    }
    jobs = std::max(1, std::min<int>(jobs, int(c.runs.size())));
    plan.overrides = options.overrides;
    plan.jobs = jobs;
    // on a terminal one progress line for all runs instead of a line per run; nothing otherwise
    plan.quiet = true;
    const bool show = !options.quiet && stderr_is_terminal();
    {  // a warning, not progress: --quiet keeps it
        std::vector<validation::Variant> variants;
        for (const auto& r : c.runs) variants.push_back(r.variant);
        std::cerr << scene_compare::long_run_note(c.scene, variants);
    }
    plan.cases.push_back(std::move(c));

    // the report is built beside the old one and swapped in whole: compare owns these entries of
    // DIR, anything else there is carried over
    std::unique_ptr<StagedDir> staged;
    try {
        staged = std::make_unique<StagedDir>(out_dir, true);
        staged->carry_over({"runs", "figures", "data", "report.md", "index.html", "replay.html", "differences.csv", "peaks.csv",
                            "energy.csv"},
                           StagedDir::Carry::link);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    const fs::path dir = staged->path();
    plan.out_dir = dir.string();
    plan.final_dir = out_dir;

    PoolProgress progress("compare " + plan.cases.front().name, plan.cases.front().runs.size(),
                          plan.cases.front().scene.run.duration);
    if (show) plan.progress = [&progress](size_t run, double f) { progress.update(run, f); };
    validation::run_plan(plan, available_backends());
    progress.clear();
    if (stop_requested()) return interrupted_keeping("report", out_dir);

    scene_compare::CompareContext ctx;
    ctx.scene_label = options.scene;
    ctx.baseline = options.baseline;
    for (const auto& b : available_backends())
        if (std::find(backends.begin(), backends.end(), b.name) != backends.end())
            ctx.backends.push_back(b);
    ctx.command = command_line(options, out_dir);
    ctx.jobs = jobs;
    std::string note;
    const validation::CaseResult& result = plan.cases.front();
    ctx.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto doc = scene_compare::write_compare_report(result, ctx, dir.string(), note);
    write_text_atomic((dir / "report.md").string(), report::to_markdown(doc));
    write_text_atomic((dir / "index.html").string(), report::to_html(doc));
    if (stop_requested()) return interrupted_keeping("report", out_dir);
    staged->commit();

    int completed = 0;
    for (const auto& r : result.runs) {
        std::printf("%-18s %s%s%s\n", r.variant.name.c_str(), validation::outcome_text(r.outcome),
                    r.message.empty() ? "" : ": ", r.message.substr(0, 160).c_str());
        completed += r.outcome == Outcome::completed;
    }
    if (!note.empty()) std::cout << "figures: " << note << "\n";
    std::printf("\nreport: %s (and report.md, differences.csv); %d of %zu variants completed\n",
                (fs::path(out_dir) / "index.html").string().c_str(), completed, result.runs.size());
    return kExitOk;
}

}  // namespace cairn
