// `cairn study contact`: the paper's node-to-face grid against the overlap integral on the
// rocking block (docs/studies.md)
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "error.hpp"
#include "output/staged_dir.hpp"
#include "registry.hpp"
#include "run/stop.hpp"
#include "scenes.hpp"
#include "study/contact_report.hpp"
#include "study/contact_study.hpp"

namespace cairn {

namespace {

/// `values` of option `name` must lie in [lo, hi]; at most 8 of them
template <class T>
void check_values(const std::vector<T>& values, const char* name, T lo, T hi, const char* unit) {
    if (values.size() > 8) throw Error(std::string(name) + ": at most 8 values");
    for (T v : values)
        if (!(v >= lo && v <= hi))
            throw Error(std::string(name) + " " + std::to_string(v) + ": expected a value in [" + std::to_string(lo) +
                        ", " + std::to_string(hi) + "] " + unit);
}

}  // namespace

CLI::App* add_study_contact(CLI::App& study, StudyContactOptions& o) {
    auto* c = study.add_subcommand("contact", "contact study: the paper's grid against the overlap integral on the rocking block");
    c->add_option("--out,-o", o.out_dir, "output directory (default out/contact)");
    c->add_option("--kn", o.kns, "contact stiffnesses kn = ks, N/m³ (default 3e7,3e8,3e9)")->delimiter(',');
    c->add_option("--spacings", o.spacings, "paper grid spacings, m (default 0.2,0.1,0.05,0.025)")->delimiter(',');
    c->add_option("--subdivisions", o.subdivisions, "overlap sub-divisions (default 1,2,4,8)")->delimiter(',');
    c->add_option("--repeats", o.repeats, "runs per point; wall time is their median (default 3)")->check(CLI::Range(1, 9));
    c->add_option("--jobs,-j", o.jobs, "runs at a time (default 2)")->check(CLI::Range(1, 64));
    c->add_flag("--quiet,-q", o.quiet, "no progress lines");
    return c;
}

int study_contact_command(const StudyContactOptions& o) {
    study::ContactStudyOptions options;
    std::unique_ptr<StagedDir> staged;
    try {
        // bounds keep every run finite: the stiffest kn sets the step, the finest grid the points
        check_values(o.kns, "--kn", 1e5, 1e12, "N/m³");
        check_values(o.spacings, "--spacings", 0.01, 1.0, "m");
        check_values(o.subdivisions, "--subdivisions", 1, 16, "");
        if (!o.kns.empty()) options.kns = o.kns;
        if (!o.spacings.empty()) options.spacings = o.spacings;
        if (!o.subdivisions.empty()) options.subdivisions = o.subdivisions;
        staged = std::make_unique<StagedDir>(o.out_dir, true);
        staged->carry_over({"contact.csv", "contact.md", "contact.html", "figures"}, StagedDir::Carry::copy);
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitBadInput;
    }
    options.repeats = o.repeats;
    options.jobs = o.jobs;
    options.quiet = o.quiet;
    const auto start = std::chrono::steady_clock::now();
    std::vector<study::ContactStudyPoint> points;
    try {
        points = study::run_contact_study(resolve_scene("paper/rocking_winkler"), options, available_backends());
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kExitFailure;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stop_requested()) return interrupted_keeping("study", o.out_dir);
    study::write_contact_study(staged->path().string(), points, wall);
    staged->commit();
    std::cout << "contact study: " << points.size() << " points in " << wall << " s; wrote " << o.out_dir
              << "/contact.csv, contact.md, contact.html\n";
    for (const auto& p : points)
        if (p.status.rfind("completed", 0) != 0) return kExitFailure;   // a run that did not complete
    return kExitOk;
}

}  // namespace cairn
