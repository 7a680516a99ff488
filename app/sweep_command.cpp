// cairn sweep: expand a plan, run it (locally, a shard of it, or as a Slurm job array), merge
#include "sweep_command.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "error.hpp"
#include "output/atomic_write.hpp"
#include "registry.hpp"
#include "run/stop.hpp"
#include "scenes.hpp"
#include "sweep/sweep_merge.hpp"
#include "sweep/sweep_result.hpp"
#include "sweep_pool.hpp"

namespace fs = std::filesystem;

namespace cairn {

namespace {

constexpr const char* kManifest = "manifest.txt";
constexpr const char* kSweepRecord = "sweep.json";

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// the outputs a sweep writes into its directory (removed by --force, nothing else is)
const std::vector<std::string> kOwned{"results", "runs", "records", "figures", "slurm", "runs.csv", "timing.csv",
                                      "fragility.csv", "report.md", "index.html", kManifest, kSweepRecord};

void remove_owned(const fs::path& dir) {
    for (const auto& n : kOwned) fs::remove_all(dir / n);
}

/// refuse a directory that holds something other than a sweep (checked before anything is written)
void check_dir_is_free(const fs::path& dir, bool force) {
    std::error_code ec;
    if (!fs::exists(dir, ec)) return;
    if (!fs::is_directory(dir, ec)) throw Error("--out " + dir.string() + ": not a directory");
    if (fs::exists(dir / kManifest) || fs::is_empty(dir, ec) || force) return;
    throw Error("--out " + dir.string() + ": not empty and holds no sweep (no " + kManifest +
                "); use an empty or new directory");
}

/// claim `dir` for `sweep`: a different sweep there is refused unless --force, results of this one
/// unless --resume or --force
void claim_dir(const sweep::Sweep& sweep, const fs::path& dir, const SweepOptions& o) {
    const std::string manifest = sweep::sweep_manifest(sweep);
    if (fs::exists(dir / kManifest)) {
        const bool same = read_text(dir / kManifest) == manifest;
        if (!same && !o.force)
            throw Error("--out " + dir.string() + ": holds another sweep (its " + kManifest + " differs from the "
                        "expansion of " + o.plan + "); use another directory, or --force to start over");
        const bool has_results = fs::exists(dir / "results") && !fs::is_empty(dir / "results");
        if (same && has_results && !o.resume && !o.force)
            throw Error("--out " + dir.string() + ": already holds results of this sweep; --resume runs only the "
                        "missing ones, --force starts over");
        if (o.force) remove_owned(dir);
    }
    fs::create_directories(dir / "results");
    if (!fs::exists(dir / kManifest) || read_text(dir / kManifest) != manifest)
        write_text_atomic((dir / kManifest).string(), manifest);
    nlohmann::ordered_json j;
    j["plan"] = fs::absolute(o.plan).lexically_normal().string();
    j["runs"] = sweep.runs.size();
    const std::string record = j.dump(2) + "\n";
    if (!fs::exists(dir / kSweepRecord) || read_text(dir / kSweepRecord) != record)
        write_text_atomic((dir / kSweepRecord).string(), record);
}

sweep::Sweep load(const std::string& plan_path, const fs::path& dir) {
    const sweep::SweepPlan plan = sweep::read_sweep_plan(plan_path, [](const std::string& s) { return resolve_scene(s); });
    return sweep::expand_sweep(plan, (dir / "records").string());
}

/// "I/N" → (I, N)
std::pair<int, int> parse_shard(const std::string& s) {
    int i = -1, n = 0;
    char rest = 0;
    if (std::sscanf(s.c_str(), "%d/%d%c", &i, &n, &rest) != 2 || n < 1 || n > 100000 || i < 0 || i >= n)
        throw Error("--shard " + s + ": expected I/N with 0 <= I < N <= 100000");
    return {i, n};
}

/// the merged table, and what is missing
int merge_and_say(const sweep::Sweep& sweep, const fs::path& dir) {
    const auto m = sweep::merge_sweep(sweep, dir.string());
    if (!m.missing.empty()) {
        std::cerr << "error: " << m.missing.size() << " of " << m.runs << " runs have no result in " << dir.string()
                  << "/results (first: " << m.missing.front() << "); run the sweep again with --resume\n";
        return kExitFailure;
    }
    std::cout << "merged " << m.runs << " runs -> " << (dir / "runs.csv").string() << "\n";
    if (sweep.plan.kind == "fragility") std::cout << "fragility report -> " << (dir / "index.html").string() << "\n";
    if (!m.note.empty()) std::cerr << "note: " << m.note << "\n";
    return kExitOk;
}

}  // namespace

int sweep_command(const SweepOptions& o) {
    fs::path dir;
    sweep::Sweep sweep;
    std::pair<int, int> shard{0, 1};
    try {
        dir = o.out_dir.empty() ? fs::path("out/sweeps") / fs::path(o.plan).stem() : fs::path(o.out_dir);
        if (!o.shard.empty()) shard = parse_shard(o.shard);
        if (!o.shard.empty() && o.scheduler == "slurm") throw Error("--shard: not with --scheduler slurm (it makes the shards)");
        check_dir_is_free(dir, o.force);
        const bool fresh = !fs::exists(dir / kManifest);
        const bool existed = fs::exists(dir);
        try {
            sweep = load(o.plan, dir);
            // every backend is built here: an unknown or missing one is bad input, before any run
            for (const auto& b : sweep.plan.backends) make_backend(sweep::backend_variant(b).backend);
        } catch (const Error&) {
            // bad input leaves nothing behind: the pulse files written for the check go
            if (fresh) fs::remove_all(dir / "records");
            if (!existed) fs::remove(dir);
            throw;
        }
        claim_dir(sweep, dir, o);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }

    if (o.scheduler == "slurm") {
        const int tasks = o.tasks > 0 ? std::min<int>(o.tasks, int(sweep.runs.size()))
                                      : std::min<int>(16, int(sweep.runs.size()));
        try {
            const auto s = submit_slurm_sweep(fs::read_symlink("/proc/self/exe").string(), o.plan, dir.string(), tasks,
                                              o.task_jobs, o.sbatch_args);
            std::cout << "submitted " << sweep.runs.size() << " runs as job array " << s.array_job << " (" << tasks
                      << " tasks) and merge job " << s.merge_job << "; the merged table will be "
                      << (dir / "runs.csv").string() << "\n";
        } catch (const Error& e) {
            std::cerr << "error: " << e.what() << "\n";
            return kExitBadInput;
        }
        return kExitOk;
    }

    // the runs of this shard without a result yet (--resume), or all of them
    const auto mine = sweep::shard_of(sweep.runs, shard.first, shard.second);
    std::vector<sweep::SweepRun> pending;
    for (const auto& r : mine)
        if (!fs::exists(sweep::result_path(dir.string(), r.id))) pending.push_back(r);
    if (!o.quiet && pending.size() < mine.size())
        std::cerr << "sweep: " << mine.size() - pending.size() << " runs already done, " << pending.size() << " to run\n";
    std::vector<RunJob> jobs;
    for (const auto& r : pending) {
        RunJob j;
        const auto v = sweep::backend_variant(r.backend);
        j.scene = r.scene;
        j.backend = v.backend;
        j.contact = v.contact;
        j.model = v.model;
        j.out_dir = sweep::run_dir(dir.string(), r.id);
        j.force = true;   // the sweep owns its run directories
        j.overrides = r.overrides;
        j.label = r.id;
        jobs.push_back(std::move(j));
    }
    std::size_t finished = 0;
    run_sweep_pool(jobs, o.jobs, [&](std::size_t i, const JobOutcome& out) {
        const auto& run = pending[i];
        ++finished;
        if (out.status == JobStatus::interrupted) return;   // no result: --resume runs it again
        sweep::SweepResult r;
        r.id = run.id;
        r.status = to_string(out.status);
        r.message = out.message;
        r.steps = out.steps;
        r.dt = out.dt;
        r.wall_seconds = out.wall_seconds;
        if (out.status == JobStatus::completed || out.status == JobStatus::unstable)
            sweep::read_trajectory_outcome(sweep::run_dir(dir.string(), run.id), run, r);
        write_text_atomic(sweep::result_path(dir.string(), run.id), sweep::result_json(run, r));
        if (!o.quiet) {
            char buf[256];
            std::snprintf(buf, sizeof buf, "sweep [%zu/%zu] %s %s %s %.4g g: %s%s, peak %.3g rad\n", finished,
                          pending.size(), run.id.c_str(), run.backend.c_str(), run.record.c_str(), run.intensity,
                          r.status.c_str(), r.overturned ? ", overturned" : "", r.peak_rotation);
            std::cerr << buf;
        }
    });
    if (stop_requested()) {
        std::cerr << "interrupted: finished runs keep their results in " << dir.string()
                  << "/results; --resume runs the rest\n";
        return kExitInterrupted;
    }
    if (!o.shard.empty()) {
        if (!o.quiet)
            std::cout << "shard " << o.shard << ": " << mine.size() << " runs have results; cairn sweep merge "
                      << dir.string() << " merges them\n";
        return kExitOk;
    }
    try {
        return merge_and_say(sweep, dir);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitFailure;
    }
}

int sweep_merge_command(const SweepOptions& o) {
    const fs::path dir = o.merge_dir;
    try {
        const fs::path record = dir / kSweepRecord;
        if (!fs::exists(record) || !fs::exists(dir / kManifest))
            throw Error(dir.string() + ": not a sweep directory (no " + kSweepRecord + " or " + kManifest + ")");
        std::string plan;
        try {
            plan = nlohmann::json::parse(read_text(record)).at("plan").get<std::string>();
        } catch (const std::exception& e) {
            throw Error(record.string() + ": no plan path (" + e.what() + ")");
        }
        const sweep::Sweep sweep = load(plan, dir);
        if (sweep::sweep_manifest(sweep) != read_text(dir / kManifest))
            throw Error(plan + ": the plan changed since the sweep in " + dir.string() +
                        " started (its expansion differs from manifest.txt)");
        return merge_and_say(sweep, dir);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
}

}  // namespace cairn
