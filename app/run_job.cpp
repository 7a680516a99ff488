#include "run_job.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <iostream>

#include "error.hpp"
#include "output/atomic_write.hpp"
#include "output/contacts_csv.hpp"
#include "output/run_files.hpp"
#include "output/staged_dir.hpp"
#include "progress_line.hpp"
#include "output/trajectory_csv.hpp"
#include "registry.hpp"
#include "run/runner.hpp"
#include "run_views.hpp"
#include "scene/scene_io.hpp"
#include "scenes.hpp"

namespace fs = std::filesystem;

namespace cairn {

std::string summary_line(const JobOutcome& o) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "%s: %lld steps, dt = %.3g s, wall %.3g s, final balance error %.3g J "
                  "(max %.2g of the energy scale%s)",
                  to_string(o.status), o.steps, o.dt, o.wall_seconds, o.final_balance_error,
                  o.max_balance_error, o.energy_drift ? ", drift flagged" : "");
    return o.energy_created.empty() ? std::string(buf) : std::string(buf) + "; " + o.energy_created;
}

namespace {

/// the contact points a run writes with --contacts
constexpr const char* kContacts = "contacts.csv";

}  // namespace

JobOutcome execute_run(const RunJob& job) {
    JobOutcome o;
    // everything that can be wrong with the input, and an output directory that cannot be
    // written, is found before the run
    Scene scene;
    std::unique_ptr<Backend> backend;
    RunRequest request;
    std::unique_ptr<StagedDir> out;
    std::unique_ptr<RunViews> views;
    try {
        request.scene_path = resolve_scene(job.scene);
        std::vector<Override> overrides;
        for (const auto& s : job.overrides) overrides.push_back(parse_override(s));
        scene = load_scene(request.scene_path, overrides);
        check_backend_tables(scene, request.scene_path);
        apply_model(scene, job.model);
        backend = make_backend(job.backend);
        if (job.contact != "rigid" && job.contact != "matched")
            throw Error("--contact " + job.contact + ": expected rigid or matched");
        views = std::make_unique<RunViews>(scene, *backend, job.backend, job.vtk, job.replay);
        out = std::make_unique<StagedDir>(job.out_dir, job.force);
        // --force replaces a run's own files; anything else in DIR comes along (hard links)
        out->carry_over({kTrajectoryFile, kPartialTrajectoryFile, kRunRecordFile, kContacts, kVtkDir, kReplayPage}, StagedDir::Carry::link);
    } catch (const Error& e) {
        o.status = JobStatus::input_error;
        o.message = e.what();
        return o;
    }
    request.overrides = job.overrides;
    request.model_override = job.model;
    request.options.contact_mode = job.contact;
    request.options.limits = job.limits;
    request.options.record_contacts = job.vtk || job.contacts;

    // the trajectory streams into the staging directory as the run goes; the set (trajectory and
    // run.json, written last) replaces DIR only when complete
    const fs::path dir = out->path();
    TrajectoryCsvFile csv((dir / kTrajectoryFile).string());
    ContactsCsvFile contacts((dir / kContacts).string(), *backend);
    RunResult result;
    // on a terminal, a progress line: simulated time, steps/s, time left
    ProgressLine progress(job.label, scene.run.duration);
    try {
        // the 3-D views (--vtk, --replay) take the samples beside the trajectory
        views->open(dir.string());
        std::vector<SampleSink*> parts{&csv, views.get()};
        if (job.contacts) parts.push_back(&contacts);
        if (job.progress) parts.push_back(&progress);
        TeeSink sinks(std::move(parts));
        result = run_scene(*backend, scene, request.options, sinks,
                           job.progress ? progress.function() : ProgressFn{});
    } catch (const Error& e) {
        o.status = JobStatus::refused;   // nothing written: the staging directory goes
        o.message = e.what();
        return o;
    }
    progress.clear();

    finish_run_files(dir.string(), scene, *backend, result, request);
    out->commit();
    o.status = outcome_of(result.status);
    o.message = result.message;
    o.steps = result.steps;
    o.dt = result.dt;
    o.wall_seconds = result.wall_seconds;
    o.energy_drift = result.energy_drift;
    o.max_balance_error = result.max_balance_error;
    o.energy_created = energy_created_text(result);
    o.warnings = result.warnings;
    if (result.sample_count > 0) o.final_balance_error = result.final_energy.total() - result.initial_total;
    return o;
}

}  // namespace cairn
