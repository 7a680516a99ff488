#include "run_job.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "error.hpp"
#include "output/atomic_write.hpp"
#include "output/run_record.hpp"
#include "output/trajectory_csv.hpp"
#include "registry.hpp"
#include "run/runner.hpp"
#include "run_views.hpp"
#include "scene/scene_io.hpp"
#include "scenes.hpp"

namespace fs = std::filesystem;

namespace cairn {

const char* to_string(JobStatus s) {
    switch (s) {
        case JobStatus::completed: return "completed";
        case JobStatus::unstable: return "unstable";
        case JobStatus::input_error: return "error";
        case JobStatus::refused: return "refused";
    }
    return "?";
}

std::string summary_line(const JobOutcome& o) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "%s: %lld steps, dt = %.3g s, wall %.3g s, final balance error %.3g J "
                  "(max %.2g of the energy scale%s)",
                  to_string(o.status), o.steps, o.dt, o.wall_seconds, o.final_balance_error,
                  o.max_balance_error, o.energy_drift ? ", drift flagged" : "");
    return buf;
}

namespace {

/// the output files a run writes; with --force these are what an earlier run may have left
constexpr const char* kTrajectory = "trajectory.csv";
constexpr const char* kPartial = "trajectory.partial.csv";
constexpr const char* kRecord = "run.json";

/// throw unless `dir` may receive outputs: absent, empty, or `force`
void check_out_dir(const fs::path& dir, bool force) {
    std::error_code ec;
    if (!fs::exists(dir, ec)) return;
    if (!fs::is_directory(dir, ec))
        throw Error("output path " + dir.string() + " exists and is not a directory");
    if (!force && !fs::is_empty(dir, ec))
        throw Error("output directory " + dir.string() +
                    " is not empty; use --force to replace an earlier run's outputs");
}

/// set every free block's model from --model
void apply_model(Scene& scene, const std::string& model) {
    if (model.empty()) return;
    BlockModel m;
    if (model == "rigid") m = BlockModel::rigid;
    else if (model == "deformable") m = BlockModel::deformable;
    else throw Error("--model " + model + ": expected rigid or deformable");
    for (auto& b : scene.blocks)
        if (!b.fixed) b.model = m;
}

/// a progress line on stderr, rewritten in place
ProgressFn progress_line(const RunJob& job) {
    if (!job.progress) return {};
    return [label = job.label](double f) {
        std::fprintf(stderr, "\r%s: %3.0f %%", label.c_str(), 100.0 * f);
        std::fflush(stderr);
    };
}

void remove_file(const fs::path& p) {
    std::error_code ec;
    fs::remove(p, ec);
}

}  // namespace

JobOutcome execute_run(const RunJob& job) {
    JobOutcome o;
    // everything that can be wrong with the input is found before anything is written
    Scene scene;
    std::unique_ptr<Backend> backend;
    RunRequest request;
    const fs::path dir = job.out_dir;
    std::unique_ptr<RunViews> views;
    try {
        request.scene_path = resolve_scene(job.scene);
        std::vector<Override> overrides;
        for (const auto& s : job.overrides) overrides.push_back(parse_override(s));
        scene = load_scene(request.scene_path, overrides);
        apply_model(scene, job.model);
        backend = make_backend(job.backend);
        check_out_dir(dir, job.force);
        if (job.contact != "rigid" && job.contact != "matched")
            throw Error("--contact " + job.contact + ": expected rigid or matched");
        views = std::make_unique<RunViews>(scene, job.backend, job.vtk, job.replay);
    } catch (const Error& e) {
        o.status = JobStatus::input_error;
        o.message = e.what();
        return o;
    }
    request.overrides = job.overrides;
    request.model_override = job.model;
    request.options.contact_mode = job.contact;
    request.options.record_contacts = job.vtk;

    // create the directory now so that a run is never lost for want of it; removed again if the
    // backend refuses the scene
    std::error_code ec;
    const bool created = !fs::exists(dir, ec);
    fs::create_directories(dir, ec);
    if (ec) {
        o.message = "cannot create output directory " + dir.string() + ": " + ec.message();
        return o;
    }

    RunResult result;
    try {
        // the 3-D views see every sample with the backend in that state
        views->open(dir.string());
        ObservedBackend observed(*backend, views->observer());
        result = run_scene(views->empty() ? *backend : observed, scene, request.options, progress_line(job));
    } catch (const Error& e) {
        if (created) fs::remove_all(dir, ec);
        o.status = JobStatus::refused;
        o.message = e.what();
        return o;
    }
    if (job.progress) std::fprintf(stderr, "\r%*s\r", int(job.label.size()) + 8, "");

    const bool completed = result.status == RunStatus::completed;
    const fs::path csv = dir / (completed ? kTrajectory : kPartial);
    write_file_atomic(csv.string(), [&](std::ostream& out) {
        write_trajectory_csv(out, scene, result.samples);
    });
    // a stale trajectory of the other kind would contradict run.json
    remove_file(dir / (completed ? kPartial : kTrajectory));
    views->finish();
    write_text_atomic((dir / kRecord).string(),
                      run_record(scene, *backend, result, request).dump(2) + "\n");

    o.status = completed ? JobStatus::completed : JobStatus::unstable;
    o.message = result.message;
    o.steps = result.steps;
    o.dt = result.dt;
    o.wall_seconds = result.wall_seconds;
    o.energy_drift = result.energy_drift;
    o.max_balance_error = result.max_balance_error;
    if (!result.samples.empty())
        o.final_balance_error =
            result.samples.back().energy.total() - result.samples.front().energy.total();
    return o;
}

}  // namespace cairn
