// `cairn validate`: every paper case on every backend variant, judged against the analytic
// references, with summary.csv, report.md, index.html and a verdict on the terminal
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "backend_option.hpp"
#include "commands.hpp"
#include "error.hpp"
#include "output/atomic_write.hpp"
#include "output/staged_dir.hpp"
#include "registry.hpp"
#include "run/stop.hpp"
#include "report/case_replay.hpp"
#include "report/figures.hpp"
#include "bench/bench_report.hpp"
#include "report/validation_report.hpp"
#include "study/contact_report.hpp"
#include "study/study_report.hpp"
#include "scene/scene_io.hpp"
#include "scenes.hpp"
#include "suggest.hpp"
#include "validation/plan.hpp"
#include "validation/run_cases.hpp"

namespace fs = std::filesystem;

namespace cairn {

namespace {

std::string join(const std::vector<std::string>& v, const char* sep) {
    std::string s;
    for (size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
    return s;
}

/// the command that reproduces this validation
std::string command_line(const ValidateOptions& o) {
    std::string c = "cairn validate --out " + o.out_dir;
    if (!o.backends.empty()) c += " --backends " + join(o.backends, ",");
    if (!o.cases.empty()) c += " --cases " + join(o.cases, ",");
    for (const auto& s : o.overrides) c += " --set " + s;
    if (o.jobs != 2) c += " --jobs " + std::to_string(o.jobs);
    return c;
}

}  // namespace

int validate_command(const ValidateOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    // every input problem is found before anything runs or is written
    std::vector<std::string> backends = options.backends;
    if (backends.empty())
        for (const auto& b : available_backends()) backends.push_back(b.name);
    std::vector<std::string> names = options.cases.empty() ? validation::paper_cases() : options.cases;
    validation::RunPlan plan;
    plan.out_dir = options.out_dir;
    plan.overrides = options.overrides;
    plan.jobs = options.jobs;
    plan.quiet = options.quiet;
    try {
        for (const auto& b : backends) make_backend(b);
        std::vector<Override> overrides;
        for (const auto& s : options.overrides) overrides.push_back(parse_override(s));
        for (const auto& n : names) {
            const auto& known = validation::paper_cases();
            if (n.find('/') == std::string::npos && std::find(known.begin(), known.end(), n) == known.end())
                throw Error("--cases " + n + ": no such case" + did_you_mean(n, known) + " (cairn validate --help lists them)");
            const std::string path = resolve_scene(n.find('/') == std::string::npos ? "paper/" + n : n);
            validation::CaseResult c;
            c.name = fs::path(n).filename().string();
            c.scene = load_scene(path, overrides);
            check_backend_tables(c.scene, path);
            if (!c.scene.reference) throw Error(path + ": no [reference] table: nothing to validate against");
            for (const auto& v : validation::variants_for(c.scene, backend_infos(backends))) {
                validation::CaseRun r;
                r.case_name = c.name;
                r.variant = v;
                c.runs.push_back(std::move(r));
            }
            plan.cases.push_back(std::move(c));
            plan.scene_paths.push_back(path);
        }
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }

    // the new report is built beside the old one and swapped in whole once complete: killed or
    // interrupted, DIR keeps the previous complete report. Validate owns these entries of DIR; the
    // rest (the study/ and bench/ written there by other commands) is carried over.
    std::unique_ptr<StagedDir> staged;
    try {
        staged = std::make_unique<StagedDir>(options.out_dir, true);
        staged->carry_over({"runs", "figures", "replays", "summary.csv", "report.md", "index.html"}, StagedDir::Carry::copy);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    const fs::path dir = staged->path();
    plan.out_dir = dir.string();
    plan.final_dir = options.out_dir;
    std::error_code ec;

    validation::run_plan(plan, available_backends());
    if (stop_requested()) {
        return interrupted_keeping("report", options.out_dir);
    }

    report::ReportContext ctx;
    for (const auto& b : available_backends())
        for (const auto& name : backends)
            if (b.name == name) ctx.backends.push_back(b);
    ctx.jobs = options.jobs;
    ctx.command = command_line(options);
    const auto figures = report::write_figures(plan.cases, dir.string());
    // one 3-D replay page per case, its variants side by side, beside the case's figures
    for (const auto& c : plan.cases) {
        std::string note;
        const std::string page = report::write_case_replay(c, dir.string(), "replays/" + c.name + ".html", note);
        if (!page.empty()) ctx.replays[c.name] = page;
        else ctx.replay_note = note;
    }
    ctx.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    auto doc = report::build_report(plan.cases, figures, ctx);
    // the inertia study and the benches, when their outputs sit beside the validation; links in the
    // report are relative to DIR, and a study or bench inside DIR is read from (and its figures
    // drawn into) the staging copy that replaces DIR
    const fs::path final_dir = staged->final_path();
    auto where = [&](const std::string& given, const char* name) {
        const fs::path shown = given.empty() ? final_dir / name : fs::absolute(given).lexically_normal();
        const fs::path inside = shown.lexically_relative(final_dir);
        const bool in_dir = !inside.empty() && *inside.begin() != "..";
        return std::make_pair(in_dir ? dir / inside : shown, fs::relative(shown, final_dir, ec).generic_string() + "/");
    };
    const auto [study_dir, study_prefix] = where(options.study_dir, "study");
    const auto [bench_dir, bench_prefix] = where(options.bench_dir, "bench");
    if (!study::add_inertia_report_section(doc, study_dir.string(), study_prefix) && !options.study_dir.empty())
        std::cerr << "note: no inertia study in " << options.study_dir << " (run cairn study inertia --out there)\n";
    const auto [contact_dir, contact_prefix] = where(options.contact_dir, "contact");
    if (!study::add_contact_report_section(doc, contact_dir.string(), contact_prefix) && !options.contact_dir.empty())
        std::cerr << "note: no contact study in " << options.contact_dir << " (run cairn study contact --out there)\n";
    const bool has_bench = fs::exists(bench_dir / "trade.csv") || fs::exists(bench_dir / "stability.csv") ||
                           fs::exists(bench_dir / "wall.csv");
    if (has_bench)
        report::append(doc, bench::bench_document(bench_dir.string()), bench_prefix);
    else if (!options.bench_dir.empty())
        std::cerr << "note: no bench results in " << options.bench_dir << " (run cairn bench all --out there)\n";
    write_text_atomic((dir / "summary.csv").string(), report::summary_csv(plan.cases));
    write_text_atomic((dir / "report.md").string(), report::to_markdown(doc));
    write_text_atomic((dir / "index.html").string(), report::to_html(doc));
    if (stop_requested()) {
        return interrupted_keeping("report", options.out_dir);
    }
    staged->commit();

    std::cout << report::verdict_text(plan.cases);
    if (!figures.note.empty()) std::cout << "figures: " << figures.note << "\n";
    std::printf("\nreport: %s (and report.md, summary.csv); %.1f s wall\n", (fs::path(options.out_dir) / "index.html").string().c_str(),
                ctx.wall_seconds);
    return kExitOk;
}

}  // namespace cairn
