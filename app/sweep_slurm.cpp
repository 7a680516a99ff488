// submitting a sweep to Slurm: a job array of shards and a merge job after it, started without a shell
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

#include "error.hpp"
#include "output/atomic_write.hpp"
#include "report/spawn.hpp"
#include "sweep_command.hpp"

namespace fs = std::filesystem;

namespace cairn {

namespace {

// the scripts are fixed text: every path comes in as an argument, never as script text
constexpr const char* kTaskScript =
    "#!/bin/sh\n"
    "# one task of a cairn sweep job array: shard $SLURM_ARRAY_TASK_ID of $4\n"
    "# arguments: cairn executable, plan file, output directory, number of tasks, runs at a time\n"
    "exec \"$1\" sweep \"$2\" --out \"$3\" --shard \"$SLURM_ARRAY_TASK_ID/$4\" --resume --jobs \"$5\" --quiet\n";
constexpr const char* kMergeScript =
    "#!/bin/sh\n"
    "# the merge of a cairn sweep, once every task of the array has ended well\n"
    "# arguments: cairn executable, output directory\n"
    "exec \"$1\" sweep merge \"$2\"\n";

/// run sbatch with `args`; the job id it prints (--parsable: "id" or "id;cluster")
std::string sbatch(const std::string& exe, const std::vector<std::string>& args, const fs::path& slurm_dir,
                   const std::string& log) {
    std::vector<std::string> argv{exe, "--parsable"};
    argv.insert(argv.end(), args.begin(), args.end());
    const int rc = report::run_program(argv, slurm_dir.string(), log);
    std::ifstream in(slurm_dir / log);
    std::ostringstream text;
    text << in.rdbuf();
    std::string id;
    for (char c : text.str()) {
        if (!std::isdigit(static_cast<unsigned char>(c))) break;
        id += c;
    }
    if (rc != 0 || id.empty())
        throw Error("sbatch failed (exit " + std::to_string(rc) + "): " + text.str() + " (see " +
                    (slurm_dir / log).string() + ")");
    return id;
}

}  // namespace

SlurmSubmission submit_slurm_sweep(const std::string& cairn_exe, const std::string& plan, const std::string& dir,
                                   int tasks, int task_jobs, const std::vector<std::string>& sbatch_args) {
    const std::string exe = report::find_on_path("sbatch");
    if (exe.empty()) throw Error("--scheduler slurm: sbatch is not on PATH (is Slurm installed here?)");
    const fs::path slurm_dir = fs::absolute(fs::path(dir) / "slurm");
    fs::create_directories(slurm_dir);
    write_text_atomic((slurm_dir / "task.sh").string(), kTaskScript);
    write_text_atomic((slurm_dir / "merge.sh").string(), kMergeScript);
    for (const char* s : {"task.sh", "merge.sh"}) fs::permissions(slurm_dir / s, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);

    const std::string abs_dir = fs::absolute(dir).lexically_normal().string();
    SlurmSubmission s;
    std::vector<std::string> array{"--job-name=cairn-sweep", "--array=0-" + std::to_string(tasks - 1),
                                   "--output=" + (slurm_dir / "task-%a.log").string()};
    array.insert(array.end(), sbatch_args.begin(), sbatch_args.end());
    for (const auto& a : {(slurm_dir / "task.sh").string(), cairn_exe, fs::absolute(plan).lexically_normal().string(),
                          abs_dir, std::to_string(tasks), std::to_string(task_jobs)})
        array.push_back(a);
    s.array_job = sbatch(exe, array, slurm_dir, "submit-array.log");
    std::vector<std::string> merge{"--job-name=cairn-sweep-merge", "--dependency=afterok:" + s.array_job,
                                   "--output=" + (slurm_dir / "merge.log").string()};
    merge.insert(merge.end(), sbatch_args.begin(), sbatch_args.end());
    for (const auto& a : {(slurm_dir / "merge.sh").string(), cairn_exe, abs_dir}) merge.push_back(a);
    s.merge_job = sbatch(exe, merge, slurm_dir, "submit-merge.log");
    write_text_atomic((slurm_dir / "jobs.txt").string(), "array " + s.array_job + "\nmerge " + s.merge_job + "\n");
    return s;
}

}  // namespace cairn
