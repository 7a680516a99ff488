#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "error.hpp"
#include "registry.hpp"
#include "run/core_pool.hpp"
#include "run/stop.hpp"
#include "scenes.hpp"

namespace cairn {

namespace {

/// one row of the summary table
struct Row {
    std::string scene, backend, status;
    JobOutcome outcome;
    bool ran = false;   ///< steps, wall time and balance error are meaningful
};

void print_table(const std::vector<Row>& rows) {
    size_t ws = 5, wb = 7;
    for (const auto& r : rows) {
        ws = std::max(ws, r.scene.size());
        wb = std::max(wb, r.backend.size());
    }
    std::printf("\n%-*s  %-*s  %-10s %10s %9s %16s\n", int(ws), "scene", int(wb), "backend",
                "status", "steps", "wall s", "final balance J");
    for (const auto& r : rows) {
        if (r.ran)
            std::printf("%-*s  %-*s  %-10s %10lld %9.3f %16.3e\n", int(ws), r.scene.c_str(),
                        int(wb), r.backend.c_str(), r.status.c_str(), r.outcome.steps,
                        r.outcome.wall_seconds, r.outcome.final_balance_error);
        else
            std::printf("%-*s  %-*s  %-10s %10s %9s %16s\n", int(ws), r.scene.c_str(), int(wb),
                        r.backend.c_str(), r.status.c_str(), "-", "-", "-");
    }
    // the reasons, below the table so that it stays readable
    bool header = false;
    for (const auto& r : rows) {
        if (r.outcome.message.empty()) continue;
        if (!header) std::printf("\nnotes:\n");
        header = true;
        std::printf("  %s on %s: %s\n", r.scene.c_str(), r.backend.c_str(), r.outcome.message.c_str());
    }
    std::fflush(stdout);
}

}  // namespace

int run_all_command(const RunAllOptions& options) {
    std::vector<std::string> backends = options.backends;
    if (backends.empty())
        for (const auto& b : available_backends()) backends.push_back(b.name);
    for (const auto& name : backends) {
        try {
            make_backend(name);
        } catch (const Error& e) {
            std::cerr << "error: " << e.what() << "\n";
            return kExitBadInput;
        }
    }
    const auto scenes = shipped_scenes();
    if (scenes.empty()) {
        std::cerr << "error: no scenes (*.toml) in " << scenarios_dir() << "\n";
        return kExitBadInput;
    }

    // every scene on every backend, in table order
    std::vector<RunJob> jobs;
    std::vector<Row> rows;
    const bool progress = !options.quiet && stderr_is_terminal();
    for (const auto& s : scenes)
        for (const auto& b : backends) {
            RunJob job;
            job.scene = s.path;
            job.backend = b;
            job.out_dir = (std::filesystem::path(options.out_dir) / s.name / b).string();
            job.force = true;   // run-all owns its output tree and replaces its own earlier outputs
            job.progress = progress;
            job.label = s.name + " on " + b;
            jobs.push_back(std::move(job));
            rows.push_back(Row{s.name, b, "", {}, false});
        }

    // one run at a time on the run layer's pool (all the cores for its OpenMP threads), so the
    // progress lines stay one after another; runs of a backend that is not thread-safe (its
    // registry facts) never overlap. Once a stop is requested no new run starts.
    std::vector<char> started(jobs.size(), 0);
    run_on_cores(
        jobs.size(), 1,
        [&](std::size_t i) {
            started[i] = 1;
            if (!options.quiet) std::cerr << "running " << jobs[i].label << "\n";
            Row& row = rows[i];
            try {
                row.outcome = execute_run(jobs[i]);
                switch (row.outcome.status) {
                    case JobStatus::completed:
                        row.status = row.outcome.energy_drift ? "drift" : "completed";
                        row.ran = true;
                        break;
                    case JobStatus::unstable:
                        row.status = "unstable";
                        row.ran = true;
                        break;
                    case JobStatus::interrupted:
                        row.status = "interrupted";
                        row.ran = true;
                        break;
                    case JobStatus::refused:
                        row.status = "skipped";
                        row.outcome.message = "skipped, the backend refuses this scene: " +
                                              row.outcome.message;
                        break;
                    case JobStatus::input_error:
                    case JobStatus::failed:
                        row.status = "FAILED";
                        break;
                }
            } catch (const std::exception& e) {
                row.status = "FAILED";
                row.outcome.message = std::string("unexpected failure: ") + e.what();
            }
        },
        [&](std::size_t i) { return !find_backend(available_backends(), jobs[i].backend).thread_safe; });

    // the runs that started (an interrupted command leaves the rest out of the table)
    std::vector<Row> ran;
    bool failed = false;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!started[i]) continue;
        failed = failed || rows[i].status == "FAILED";
        ran.push_back(std::move(rows[i]));
    }
    print_table(ran);
    const auto where = std::filesystem::path(options.out_dir) / "<scene>" / "<backend>";
    std::printf("\noutputs in %s\n", where.string().c_str());
    if (stop_requested()) {
        std::cerr << "interrupted: runs not started are missing from the table\n";
        return kExitInterrupted;
    }
    return failed ? kExitFailure : kExitOk;
}

}  // namespace cairn
