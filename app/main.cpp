// the cairn executable: run scenes on backends, list what is available
#include <algorithm>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "wait_policy.hpp"
#include "run/stop.hpp"
#include "limit_options.hpp"
#include "suggest.hpp"
#include "sweep_command.hpp"
#include "validation/plan.hpp"

int main(int argc, char** argv) {
    using namespace cairn;
    ensure_passive_openmp_wait(argv);
    // the name is fixed so that usage lines say "cairn", not the path it was started by
    CLI::App app{"cairn: a testbed for masonry block dynamics (scenes on several engines)", "cairn"};
    app.set_version_flag("--version", std::string("cairn ") + CAIRN_VERSION);
    app.require_subcommand(1);

    RunJob job;
    bool quiet = false;
    auto* run = app.add_subcommand("run", "run one scene on one backend");
    run->add_option("scene", job.scene, "scene file, or a shipped scene name (paper/stability)")
        ->required();
    run->add_option("--backend,-b", job.backend, "backend name (cairn list)")->required();
    run->add_option("--out,-o", job.out_dir, "output directory")->required();
    run->add_flag("--force", job.force, "write into a non-empty directory, replacing old outputs");
    run->add_option("--set", job.overrides, "override a scene key: --set key=value (repeatable)")
        ->take_all()
        ->allow_extra_args(false);
    run->add_option("--model", job.model, "model of every free block")
        ->check(CLI::IsMember({"rigid", "deformable"}));
    run->add_option("--contact", job.contact, "contact mode of the reference engines")
        ->check(CLI::IsMember({"rigid", "matched"}));
    run->add_flag("--vtk", job.vtk, "also write the run for ParaView into DIR/vtk/ (docs/visualisation.md)");
    run->add_flag("--replay", job.replay, "also write the interactive 3-D replay DIR/replay.html");
    run->add_flag("--contacts", job.contacts, "also write every sample's contact points and forces to DIR/contacts.csv");
    run->add_flag("--quiet,-q", quiet, "no progress line and no summary");
    add_limit_options(*run, job.limits);

    app.add_subcommand("list", "list the shipped scenes and the backends with their capabilities");

    ReplayOptions replay;
    auto* replay_cmd = app.add_subcommand("replay", "the 3-D replay of runs side by side, one HTML page (docs/visualisation.md)");
    replay_cmd->add_option("runs", replay.run_dirs, "directories written by cairn run")->required();
    replay_cmd->add_option("--out,-o", replay.out, "the page to write (default replay.html)");
    replay_cmd->add_option("--title", replay.title, "page title");

    RunAllOptions all;
    auto* run_all = app.add_subcommand("run-all", "run every shipped scene on every backend");
    run_all->add_option("--out,-o", all.out_dir, "output directory (default out)");
    run_all->add_option("--backends", all.backends, "comma-separated backend names")
        ->delimiter(',');
    run_all->add_flag("--quiet,-q", all.quiet, "no progress lines");

    StudyInertiaOptions inertia;
    auto* study = app.add_subcommand("study", "studies of the engine's numerical choices");
    study->require_subcommand(1);
    auto* study_inertia = study->add_subcommand("inertia", "mesh-inertia study: mass schemes x mesh on rocking and impact");
    study_inertia->add_option("--out,-o", inertia.out_dir, "output directory (default out/study)");
    study_inertia->add_option("--repeats", inertia.repeats, "runs per point; wall time is their median (default 3)")
        ->check(CLI::Range(1, 9));
    study_inertia->add_option("--jobs,-j", inertia.jobs, "runs at a time (default 2)")->check(CLI::Range(1, 64));
    study_inertia->add_option("--n", inertia.ns, "elements per side (default 1,2,4,8)")->delimiter(',');
    study_inertia->add_flag("--quiet,-q", inertia.quiet, "no progress lines");
    StudyContactOptions contact;
    auto* study_contact = add_study_contact(*study, contact);
    StudyOverturningOptions overturning;
    auto* study_overturning = add_study_overturning(*study, overturning);
    StudyRecordOptions record;
    auto* study_record = add_study_record(*study, record);

    CompareOptions cmp;
    auto* compare = app.add_subcommand("compare", "run one scene on every backend variant and compare them in a report");
    compare->add_option("scene", cmp.scene, "scene file, or a shipped scene name (cairn list)")->required();
    compare->add_option("--backends", cmp.backends, "all, or comma-separated backend names (default all)")
        ->delimiter(',');
    compare->add_option("--model", cmp.model, "block model of the dem runs: rigid, deformable or both (default both)")
        ->check(CLI::IsMember({"rigid", "deformable", "both"}));
    compare->add_option("--out,-o", cmp.out_dir, "report directory (default out/compare/<scene>)");
    compare->add_option("--jobs,-j", cmp.jobs, "runs at a time (default: the machine's cores)")->check(CLI::Range(1, 64));
    compare->add_option("--baseline", cmp.baseline, "variant the others are compared with (default dem-rigid)");
    compare->add_option("--set", cmp.overrides, "override a scene key: --set key=value (repeatable)")
        ->take_all()
        ->allow_extra_args(false);
    compare->add_flag("--quiet,-q", cmp.quiet, "no progress lines");

    MakeOptions make;
    const auto make_cmds = add_make_commands(app, make);

    ValidateOptions val;
    auto* validate = app.add_subcommand("validate", "run the paper's cases on every backend and write the report");
    {
        std::string cases = "Cases (scenarios/paper/):";
        for (const auto& c : validation::paper_cases()) cases += " " + c;
        validate->footer(cases);
    }
    validate->add_option("--out,-o", val.out_dir, "output directory (default out/validation)");
    validate->add_option("--backends", val.backends, "comma-separated backend names")->delimiter(',');
    validate->add_option("--cases", val.cases, "comma-separated case names (default: all)")->delimiter(',');
    validate->add_option("--set", val.overrides, "override a key of every scene: --set key=value (repeatable)")
        ->take_all()
        ->allow_extra_args(false);
    validate->add_option("--jobs,-j", val.jobs, "runs at a time (default 2)")->check(CLI::Range(1, 64));
    validate->add_flag("--quiet,-q", val.quiet, "no progress lines");
    validate->add_option("--study", val.study_dir,
                         "include the inertia study written there by `cairn study inertia` (default: DIR/study if present)");
    validate->add_option("--contact", val.contact_dir,
                         "include the contact study written there by `cairn study contact` (default: DIR/contact if present)");
    validate->add_option("--bench", val.bench_dir,
                         "include the bench results written there by `cairn bench` (default: DIR/bench if present)");

    BenchOptions bench;
    auto* bench_cmd = app.add_subcommand("bench", "speed against accuracy, stability, throughput (docs/bench.md)");
    bench_cmd->require_subcommand(1);
    for (const char* which : {"trade", "stability", "wall", "scale", "all"}) {
        auto* sub = bench_cmd->add_subcommand(which, std::string("cairn bench ") + which);
        sub->add_option("--out,-o", bench.out_dir, "output directory (default out/bench)");
        sub->add_option("--backends", bench.backends, "comma-separated backend names")->delimiter(',');
        sub->add_option("--jobs,-j", bench.jobs, "runs at a time (default 2)")->check(CLI::Range(1, 64));
        sub->add_option("--repeats", bench.repeats, "runs per point; median wall time (default 3)")->check(CLI::Range(1, 9));
        sub->add_flag("--quiet,-q", bench.quiet, "no progress lines");
        if (std::string(which) == "trade" || std::string(which) == "all") {
            sub->add_option("--cases", bench.cases, "rocking,rocking_slender,impact (default all)")->delimiter(',');
            sub->add_flag("--full", bench.full, "the big sweep");
            sub->add_flag("--quick", bench.quick, "two or three points per backend");
        }
        if (std::string(which) == "stability" || std::string(which) == "all")
            sub->add_option("--long-steps", bench.long_steps, "steps of the long resting run (default 1e6)");
        if (std::string(which) == "wall" || std::string(which) == "all") {
            sub->add_option("--courses", bench.courses, "courses of 10 bricks (default 30)")->check(CLI::Range(1, 200));
            sub->add_option("--steps", bench.wall_steps, "steps per repeat (default 200)")->check(CLI::Range(1, 100000));
        }
        if (std::string(which) == "scale") {
            sub->add_option("--sizes", bench.scale_sizes, "bricks per wall (default 1000,3000,10000)")
                ->delimiter(',')
                ->check(CLI::Range(10, 20000));
            sub->add_option("--steps", bench.scale_steps, "steps timed per wall (default 5)")->check(CLI::Range(1, 10000));
            sub->add_flag("!--no-pushover", bench.pushover, "skip the wall pushover accuracy measure");
            sub->add_flag("--large", bench.large, "only the ~1e4-brick tower under El Centro on dem (minutes)");
            sub->add_option("--large-blocks", bench.large_blocks, "--large: bricks of the tower (default 10000)")
                ->check(CLI::Range(10, 20000));
            sub->add_option("--large-duration", bench.large_duration, "--large: simulated seconds of the record (default 1)")
                ->check(CLI::Range(0.001, 30.0));
        }
    }

    SweepOptions sweep;
    auto* sweep_cmd = app.add_subcommand("sweep", "a plan of independent runs, locally or on Slurm, merged into one table (docs/sweeps.md)");
    sweep_cmd->add_option("plan", sweep.plan, "the sweep plan (TOML)");
    sweep_cmd->add_option("--out,-o", sweep.out_dir, "output directory (default out/sweeps/<plan name>)");
    sweep_cmd->add_option("--jobs,-j", sweep.jobs, "runs at a time (default 2)")->check(CLI::Range(1, 64));
    sweep_cmd->add_option("--shard", sweep.shard, "run only shard I of N (I/N, 0-based; merge later)");
    sweep_cmd->add_flag("--resume", sweep.resume, "skip the runs that have a result");
    sweep_cmd->add_flag("--force", sweep.force, "start over in a directory holding a sweep");
    sweep_cmd->add_option("--scheduler", sweep.scheduler, "local (default) or slurm (a job array and a merge job)")
        ->check(CLI::IsMember({"local", "slurm"}));
    sweep_cmd->add_option("--tasks", sweep.tasks, "slurm: array tasks (default min(runs, 16))")->check(CLI::Range(1, 10000));
    sweep_cmd->add_option("--task-jobs", sweep.task_jobs, "slurm: runs at a time in each task (default 1)")->check(CLI::Range(1, 64));
    sweep_cmd->add_option("--sbatch-arg", sweep.sbatch_args, "slurm: an extra sbatch option, e.g. --sbatch-arg=--partition=short (repeatable)")
        ->take_all()
        ->allow_extra_args(false);
    sweep_cmd->add_flag("--quiet,-q", sweep.quiet, "no progress lines");
    auto* sweep_merge = sweep_cmd->add_subcommand("merge", "merge the results in DIR into runs.csv (and the fragility report)");
    sweep_merge->add_option("dir", sweep.merge_dir, "the sweep's output directory")->required();

    // bare `cairn`: the usage and the commands, exit 2 (a command is required)
    if (argc < 2) {
        std::cout << app.help();
        return kExitBadInput;
    }
    // a first word that is no option and no command: say which command was meant
    if (argv[1][0] != '-') {
        std::vector<std::string> names;
        for (const auto* sub : app.get_subcommands({})) names.push_back(sub->get_name());
        if (std::find(names.begin(), names.end(), std::string(argv[1])) == names.end()) {
            std::string all;
            for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
            std::cerr << "error: unknown command '" << argv[1] << "'" << did_you_mean(argv[1], names)
                      << "\ncommands: " << all << " (cairn --help)\n";
            return kExitBadInput;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kExitOk : kExitBadInput;
    }

    // Ctrl-C and SIGTERM stop runs at their next step boundary (the partial result is kept and
    // marked); a second one ends the process at once
    install_stop_handlers();
    try {
        if (app.got_subcommand(run)) return run_command(job, quiet);
        if (app.got_subcommand("list")) return list_command();
        if (app.got_subcommand(replay_cmd)) return replay_command(replay);
        if (app.got_subcommand(run_all)) return run_all_command(all);
        if (study_inertia->parsed()) return study_inertia_command(inertia);
        if (study_contact->parsed()) return study_contact_command(contact);
        if (study_overturning->parsed()) return study_overturning_command(overturning);
        if (study_record->parsed()) return study_record_command(record);
        if (app.got_subcommand(validate)) return validate_command(val);
        if (app.got_subcommand(compare)) return compare_command(cmp);
        if (sweep_merge->parsed()) return sweep_merge_command(sweep);
        if (app.got_subcommand(sweep_cmd)) {
            if (sweep.plan.empty()) {
                std::cerr << "error: cairn sweep: a plan file is required (or: cairn sweep merge DIR)\n";
                return kExitBadInput;
            }
            return sweep_command(sweep);
        }
        for (auto* sub : make_cmds)
            if (sub->parsed()) return make_command(sub->get_name(), make);
        for (auto* sub : bench_cmd->get_subcommands())
            if (sub->parsed()) return bench_command(sub->get_name(), bench);
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitFailure;
    }
    return kExitFailure;
}
