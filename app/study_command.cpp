// `cairn study inertia`: the mesh-inertia study (docs/inertia.md); `cairn study overturning` (docs/studies.md)
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>

#include "backend_option.hpp"
#include "commands.hpp"
#include "error.hpp"
#include "output/staged_dir.hpp"
#include "registry.hpp"
#include "run/stop.hpp"
#include "scenes.hpp"
#include "study/inertia_study.hpp"
#include "study/overturning_study.hpp"
#include "study/record_study.hpp"
#include "scene/scene_io.hpp"
#include "suggest.hpp"
#include "study/study_report.hpp"

namespace cairn {

namespace {

/// true for a backend whose runs must not overlap (its registry facts)
bool not_thread_safe(const std::string& name) { return !find_backend(available_backends(), name).thread_safe; }

}  // namespace

int study_inertia_command(const StudyInertiaOptions& o) {
    // built beside the old study and swapped in whole once complete
    std::unique_ptr<StagedDir> staged;
    try {
        staged = std::make_unique<StagedDir>(o.out_dir, true);
        staged->carry_over({"inertia.csv", "inertia.md", "inertia.html", "figures"}, StagedDir::Carry::copy);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    study::StudyOptions options;
    if (!o.ns.empty()) options.ns = o.ns;
    options.repeats = o.repeats;
    options.jobs = o.jobs;
    options.quiet = o.quiet;
    const auto start = std::chrono::steady_clock::now();
    const auto points = study::run_study(study::default_cases(scenarios_dir()), options,
                                         available_backends(),
                                         find_backend(available_backends(), "dem").block_inertia);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stop_requested()) {
        return interrupted_keeping("study", o.out_dir);
    }
    study::write_inertia_study(staged->path().string(), points, wall);
    staged->commit();
    std::cout << "inertia study: " << points.size() << " points in " << wall << " s; wrote " << o.out_dir
              << "/inertia.csv, inertia.md, inertia.html\n";
    for (const auto& p : points)
        if (p.status != "completed") return kExitFailure;
    return kExitOk;
}

namespace {

/// the options the overturning and record studies share
void add_common(CLI::App& c, std::vector<double>& block, std::vector<std::string>& backends, int& jobs,
                std::vector<std::string>& overrides, std::string& out, bool& quiet) {
    c.add_option("--block", block, "W,H[,D]: a block W wide (x), H high, D deep (default D = W) on a slab, m")
        ->delimiter(',')->expected(2, 3);
    c.add_option("--backends", backends, "all, or comma-separated backend names (default all)")->delimiter(',');
    c.add_option("--jobs,-j", jobs, "runs at a time (default 2)")->check(CLI::Range(1, 64));
    c.add_option("--set", overrides, "override a key of every backend scene: --set key=value (repeatable)");
    c.add_option("--out,-o", out, "output directory (default " + out + ")");
    c.add_flag("--quiet,-q", quiet, "no progress lines");
}

}  // namespace

CLI::App* add_study_overturning(CLI::App& study, StudyOverturningOptions& o) {
    auto* c = study.add_subcommand("overturning", "overturning spectra under pulses: every backend against the rocking oracle");
    c->add_option("scene", o.scene, "scene with one upright free box on a fixed base (or give --block)");
    add_common(*c, o.block, o.backends, o.jobs, o.overrides, o.out_dir, o.quiet);
    c->add_option("--pulse", o.pulse, "sine, cosine or ricker (default sine)");
    c->add_option("--grid", o.grid, "NxM: N amplitudes a_p/(g tan a) x M frequencies w_p/p (default 8x9)");
    c->add_option("--levels", o.levels, "the grid's amplitudes a_p/(g tan a), ascending (instead of --grid's)")
        ->delimiter(',');
    c->add_option("--ratios", o.ratios, "the grid's frequencies w_p/p, ascending (instead of --grid's)")->delimiter(',');
    c->add_option("--bisect", o.bisect, "bisection steps of each minimum overturning amplitude (default 10)")
        ->check(CLI::Range(0, 40));
    return c;
}

namespace {

/// the scene file's text
std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw Error(path + ": cannot read the scene");
    return text.str();
}

/// `s` as a TOML basic string
std::string toml_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (static_cast<unsigned char>(c) < 0x20) throw Error("--record: the path has a control character");
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

/// N amplitudes from 1.5 to 12 g tan a (the default 8 listed) and M frequencies from 1 to 9 p
void parse_grid(const std::string& text, study::OverturningSetup& s) {
    int n = 0, m = 0;
    char x = 0, extra = 0;
    std::istringstream in(text);
    if (!(in >> n >> x >> m) || x != 'x' || (in >> extra) || n < 2 || m < 1 || n > 100 || m > 100)
        throw Error("--grid " + text + ": expected NxM with N in [2, 100] amplitudes and M in [1, 100] frequencies");
    s.levels = n == 8 ? study::default_levels() : std::vector<double>{};
    for (int i = 0; n != 8 && i < n; ++i) s.levels.push_back(1.5 * std::pow(8.0, double(i) / (n - 1)));
    s.ratios = m == 9 ? study::default_ratios() : std::vector<double>{};
    for (int i = 0; m != 9 && i < m; ++i) s.ratios.push_back(m == 1 ? 5.0 : 1.0 + 8.0 * i / (m - 1));
}

/// the setup of the options: the block (from --block or the scene's free box), grid and backends
study::OverturningSetup overturning_setup(const StudyOverturningOptions& o) {
    study::OverturningSetup s;
    if (o.scene.empty() == o.block.empty())
        throw Error("study overturning: give a scene or --block W,H[,D], not both");
    if (!o.block.empty()) {
        const double w = o.block[0], h = o.block[1], d = o.block.size() > 2 ? o.block[2] : o.block[0];
        s.scene_text = study::block_scene_text(w, d, h);
        s.scene_source = "--block";
    } else {
        s.scene_source = resolve_scene(o.scene);
        s.scene_text = read_text(s.scene_source);
    }
    for (const auto& ov : o.overrides) s.overrides.push_back(parse_override(ov));
    const Scene scene = parse_scene(s.scene_text, s.scene_source, s.overrides);
    if (scene.ground_motion)
        throw Error(s.scene_source + ": [ground_motion]: the study applies its own pulses; remove the scene's record");
    const auto rb = study::rocking_block_of(scene);
    s.b = rb.b;
    s.h = rb.h;
    s.g = rb.g;
    s.pulse = oracle::parse_pulse_shape(o.pulse);
    parse_grid(o.grid, s);
    auto take = [](const std::vector<double>& given, std::vector<double>& into, const char* name) {
        if (given.empty()) return;
        for (size_t i = 0; i < given.size(); ++i)
            if (!(given[i] > 0.0 && given[i] <= 1000.0) || (i > 0 && !(given[i] > given[i - 1])))
                throw Error(std::string(name) + ": values must be ascending in (0, 1000]");
        into = given;
    };
    take(o.levels, s.levels, "--levels");
    take(o.ratios, s.ratios, "--ratios");
    if (s.levels.size() < 2) throw Error("--levels: at least 2 amplitudes");
    s.backends = chosen_backends(o.backends);
    s.bisect = o.bisect;
    s.jobs = o.jobs;
    s.quiet = o.quiet;
    return s;
}

}  // namespace

int study_overturning_command(const StudyOverturningOptions& o) {
    std::unique_ptr<StagedDir> staged;
    study::OverturningSetup setup;
    try {
        setup = overturning_setup(o);
        staged = std::make_unique<StagedDir>(o.out_dir, true);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    setup.exclusive = not_thread_safe;
    study::OverturningResult result;
    try {
        result = study::run_overturning(setup, make_backend);
    } catch (const Error& e) {
        if (stop_requested()) return interrupted_keeping("study", o.out_dir);
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    study::write_overturning_study(staged->path().string(), setup, result);
    staged->commit();
    std::cout << "overturning study: " << result.grid.size() + result.bisection.size() << " runs in "
              << result.wall_seconds << " s; wrote " << o.out_dir << "/overturning.md, overturning.html\n";
    return kExitOk;
}

CLI::App* add_study_record(CLI::App& study, StudyRecordOptions& o) {
    auto* c = study.add_subcommand("record", "rocking under a record: every backend's theta(t) against the rocking oracle");
    c->add_option("scene", o.scene, "scene with one upright free box and a [ground_motion] along x (or give --block)");
    add_common(*c, o.block, o.backends, o.jobs, o.overrides, o.out_dir, o.quiet);
    c->add_option("--record", o.record, "with --block: a CSV of t_s, accel_g (default the shipped El Centro 1940 NS)");
    c->add_option("--duration", o.duration, "with --block: simulated time, s (default 10)")->check(CLI::Range(0.01, 600.0));
    return c;
}

int study_record_command(const StudyRecordOptions& o) {
    std::unique_ptr<StagedDir> staged;
    study::RecordSetup setup;
    try {
        if (o.scene.empty() == o.block.empty()) throw Error("study record: give a scene or --block W,H[,D], not both");
        if (!o.block.empty()) {
            const double w = o.block[0], h = o.block[1], d = o.block.size() > 2 ? o.block[2] : o.block[0];
            const std::string rec = std::filesystem::absolute(
                o.record.empty() ? scenarios_dir() + "/data/elcentro_1940_ns.csv" : o.record).string();
            setup.scene_text = study::block_scene_text(w, d, h) + "\n[ground_motion]\nfile = " + toml_string(rec) +
                               "\nunits = \"g\"\ndirection = [1.0, 0.0, 0.0]\n";
            setup.scene_source = "--block";
            setup.overrides.push_back({"run.duration", std::to_string(o.duration)});
        } else {
            if (!o.record.empty()) throw Error("--record: give the record in the scene's [ground_motion] (or use --block)");
            setup.scene_source = resolve_scene(o.scene);
            setup.scene_text = read_text(setup.scene_source);
        }
        for (const auto& ov : o.overrides) setup.overrides.push_back(parse_override(ov));
        setup.backends = chosen_backends(o.backends);
        setup.jobs = o.jobs;
        setup.quiet = o.quiet;
        staged = std::make_unique<StagedDir>(o.out_dir, true);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    study::RecordResult result;
    try {
        setup.exclusive = not_thread_safe;
        result = study::run_record_study(setup, make_backend);
    } catch (const Error& e) {
        if (stop_requested()) return interrupted_keeping("study", o.out_dir);
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    study::write_record_study(staged->path().string(), result);
    staged->commit();
    std::cout << "record study: wrote " << o.out_dir << "/record.md, record.html\n";
    for (const auto& h : result.histories)
        std::cout << "  " << h.method << ": parts from the oracle at "
                  << (std::isfinite(h.parting) ? std::to_string(h.parting) + " s" : "never") << "\n";
    return kExitOk;
}

}  // namespace cairn
