// `cairn study inertia`: the mesh-inertia study (docs/inertia.md)
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "dem/deformable/deformable_body.hpp"
#include "dem/mesh.hpp"
#include "error.hpp"
#include "output/staged_dir.hpp"
#include "registry.hpp"
#include "run/stop.hpp"
#include "scenes.hpp"
#include "study/inertia_study.hpp"
#include "study/study_report.hpp"

namespace cairn {

namespace {

/// the dem engine's own assembled rotational inertia of block b (about its centre, block axes)
Mat3 dem_inertia(const Scene& scene, int b) {
    const BlockDef& d = scene.blocks.at(size_t(b));
    const dem::Mesh mesh = dem::make_mesh(d.corners, d.mesh.divisions);
    const std::vector<char> fixed(mesh.nodes.size(), 0);
    // on the heap, as the engine builds it (aligned members)
    const auto body = std::make_shared<dem::DeformableBody>(mesh, scene.materials.at(size_t(d.material)),
                                                            d.mesh.mass, 0.0, fixed);
    return body->inertia();
}

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
                                         available_backends(), dem_inertia);
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

}  // namespace cairn
