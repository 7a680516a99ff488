#include "run/run_jobs.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <mutex>

#include "error.hpp"
#include "output/run_files.hpp"
#include "output/trajectory_csv.hpp"
#include "run/core_pool.hpp"
#include "scene/scene_io.hpp"

namespace fs = std::filesystem;

namespace cairn {

const char* to_string(Outcome o) {
    switch (o) {
        case Outcome::completed: return "completed";
        case Outcome::unstable: return "unstable";
        case Outcome::interrupted: return "interrupted";
        case Outcome::refused: return "refused";
        case Outcome::input_error: return "error";
        case Outcome::failed: return "failed";
    }
    return "?";
}

Outcome outcome_of(RunStatus s) {
    switch (s) {
        case RunStatus::completed: return Outcome::completed;
        case RunStatus::unstable: return Outcome::unstable;
        case RunStatus::interrupted: return Outcome::interrupted;
    }
    return Outcome::failed;
}

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

std::string job_key(const RunSpec& job) {
    const RunOptions& o = job.options;
    const std::string options = "contact_mode=" + o.contact_mode +
                                " allow_large=" + std::to_string(o.limits.allow_large) +
                                " allow_unstable_dt=" + std::to_string(o.limits.allow_unstable_dt) +
                                " memory_budget=" + message_number(o.limits.memory_budget, 17) +
                                " record_contacts=" + std::to_string(o.record_contacts);
    const std::string scene = job.scene ? scene_to_json(*job.scene).dump() : "";
    return text_hash(scene + '\n' + job.backend + '\n' + options);
}

namespace {

/// the outcome named by to_string (failed when none is)
Outcome outcome_named(const std::string& name) {
    for (Outcome o : {Outcome::completed, Outcome::unstable, Outcome::interrupted, Outcome::refused,
                      Outcome::input_error, Outcome::failed})
        if (name == to_string(o)) return o;
    return Outcome::failed;
}

/// the first run of a job: with files, streamed to out_dir/trajectory.csv and ended by run.json
RunResult first_run(const RunSpec& job, const BackendInfo& info, const ProgressFn& progress, JobResult& r) {
    auto backend = info.make();
    if (job.out_dir.empty()) {
        if (job.keep_samples) return run_scene(*backend, *job.scene, job.options, progress);
        NullSink none;
        return run_scene(*backend, *job.scene, job.options, none, progress);
    }
    const fs::path dir(job.out_dir);
    CollectingSink collect;
    TrajectoryCsvFile csv((dir / kTrajectoryFile).string());
    std::vector<SampleSink*> parts{&csv};
    if (job.keep_samples) parts.push_back(&collect);
    TeeSink sink(std::move(parts));
    RunResult result;
    try {
        fs::create_directories(dir);
        result = run_scene(*backend, *job.scene, job.options, sink, progress);
    } catch (const Error&) {
        std::error_code ec;
        fs::remove_all(dir, ec);   // refused before the first sample: nothing of it is kept
        throw;
    }
    result.samples = std::move(collect.samples);
    try {
        finish_run_files(dir.string(), *job.scene, *backend, result, job.request);
    } catch (const std::exception& e) {
        r.outcome = Outcome::failed;
        r.message = std::string("cannot write outputs: ") + e.what();
    }
    return result;
}

/// one job, never throws
JobResult execute(const RunSpec& job, const BackendInfo* info, const JobsOptions& options, const ProgressFn& progress) {
    JobResult r;
    std::vector<double> walls;
    try {
        if (!info) throw Error("no backend");
        for (int k = 0; k < std::max(1, job.repeats); ++k) {
            if (k == 0) {
                r.outcome = Outcome::completed;
                RunResult res = first_run(job, *info, progress, r);
                if (r.outcome == Outcome::completed) r.outcome = outcome_of(res.status);
                if (r.message.empty()) r.message = res.message;
                walls.push_back(res.wall_seconds);
                r.result = std::move(res);
                // a blow-up's wall time means nothing; a long run's is steady enough
                if (r.outcome != Outcome::completed || r.result.wall_seconds >= options.repeat_below) break;
            } else {
                auto backend = info->make();
                NullSink none;
                walls.push_back(run_scene(*backend, *job.scene, job.options, none).wall_seconds);
            }
        }
    } catch (const Error& e) {
        r.outcome = Outcome::refused;
        r.message = e.what();
    } catch (const std::exception& e) {
        r.outcome = Outcome::failed;
        r.message = std::string("unexpected failure: ") + e.what();
    }
    r.median_wall = median(walls);
    return r;
}

}  // namespace

std::size_t run_jobs(const std::vector<RunSpec>& jobs, const std::vector<BackendInfo>& backends,
                     const JobsOptions& options, const std::function<void(std::size_t, JobResult&)>& done) {
    // resume: the jobs the log holds are handed over as kept, the others run
    std::vector<std::string> keys(options.resume ? jobs.size() : 0);
    std::vector<size_t> to_run;
    for (size_t i = 0; i < jobs.size(); ++i) {
        if (options.resume) {
            keys[i] = job_key(jobs[i]);
            if (const ResumeLog::Entry* kept = options.resume->find(keys[i])) {
                JobResult r;
                r.resumed = true;
                r.outcome = outcome_named(kept->outcome);
                r.record = kept->record;
                if (done) done(i, r);
                continue;
            }
        }
        to_run.push_back(i);
    }
    // the facts of each job's backend, looked up once (an unknown name: the job is refused)
    std::vector<const BackendInfo*> info(jobs.size(), nullptr);
    std::vector<std::string> unknown(jobs.size());
    for (size_t i = 0; i < jobs.size(); ++i) {
        try {
            info[i] = &find_backend(backends, jobs[i].backend);
        } catch (const Error& e) {
            unknown[i] = e.what();
        }
    }
    std::mutex print;
    size_t finished = 0;
    run_on_cores(
        to_run.size(), options.jobs,
        [&](size_t k) {
            const size_t i = to_run[k];
            ProgressFn progress;
            if (options.progress) progress = [&options, i](double f) { options.progress(i, f); };
            JobResult r;
            if (!unknown[i].empty()) {
                r.outcome = Outcome::refused;
                r.message = unknown[i];
            } else {
                r = execute(jobs[i], info[i], options, progress);
            }
            if (options.progress) options.progress(i, 1.0);
            {
                std::lock_guard<std::mutex> lock(print);
                ++finished;
                if (!options.quiet)
                    std::fprintf(stderr, "%s [%zu/%zu] %s %s: %s, %.3g s\n", options.tag.c_str(), finished, to_run.size(),
                                 jobs[i].backend.c_str(), jobs[i].label.c_str(), to_string(r.outcome), r.median_wall);
            }
            if (done) done(i, r);
            const bool final = r.outcome == Outcome::completed || r.outcome == Outcome::unstable ||
                               r.outcome == Outcome::refused;
            if (options.resume && final) {
                try {
                    options.resume->keep(keys[i], {to_string(r.outcome), r.record});
                } catch (const std::exception& e) {
                    std::lock_guard<std::mutex> lock(print);
                    std::fprintf(stderr, "%s: %s (the job will run again on resume)\n", options.tag.c_str(), e.what());
                }
            }
        },
        [&](size_t k) { const size_t i = to_run[k]; return info[i] && !info[i]->thread_safe; });
    return to_run.size();
}

}  // namespace cairn
