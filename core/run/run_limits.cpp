#include "run/run_limits.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "error.hpp"
#include "scene/scene.hpp"

namespace cairn {

namespace {

std::string g(double x) { return message_number(x, 4); }

// "run.dt = 1e-30" or "run.dt = auto (2e-5 s from the critical step, contact.kn = 1e9)"
std::string dt_text(const Scene& scene, double dt, double critical) {
    if (scene.run.dt) return "run.dt = " + g(*scene.run.dt);
    std::string s = "run.dt = auto gave " + g(dt) + " s";
    if (critical > 0.0) s += " from the critical step " + g(critical) + " s";
    s += " (contact.kn = " + g(scene.contact.kn);
    double young = 0.0;
    for (const auto& b : scene.blocks)
        if (b.model == BlockModel::deformable && !b.fixed)
            young = std::max(young, scene.materials[size_t(b.material)].young);
    if (young > 0.0) s += ", stiffest deformable material young = " + g(young);
    return s + ")";
}

}  // namespace

RunSize check_run_size(const Scene& scene, const std::string& backend, double dt, double critical,
                       const RunLimits& limits) {
    const std::string where = scene.source + ": ";
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw Error(where + dt_text(scene, dt, critical) + ": backend " + backend + " cannot step with dt = " +
                    g(dt) + " s (it must be positive and finite)");
    if (scene.run.dt && critical > 0.0 && dt > critical && !limits.allow_unstable_dt)
        throw Error(where + "run.dt = " + g(dt) + ": above the critical step " + g(critical) + " s of backend " +
                    backend + " (" + g(dt / critical) + " times); the run would blow up. Use run.dt = \"auto\" or a "
                    "step below the critical one, or --allow-unstable-dt to run it anyway");
    const double steps = std::max(0.0, std::ceil(scene.run.duration / dt - 1e-9));
    // 2^62: beyond it a step count no longer fits the counters, whatever the flags
    const double hard = 4.6e18;
    if (steps > hard || (steps > kMaxSteps && !limits.allow_large))
        throw Error(where + "run.duration = " + g(scene.run.duration) + " s with " + dt_text(scene, dt, critical) +
                    " is " + g(steps) + " steps, beyond the limit of " + g(kMaxSteps) + " steps " +
                    (steps > hard ? std::string("(and too many to count even with --allow-large)")
                                  : std::string("(--allow-large lifts it: a billion steps take hours of CPU)")));
    RunSize size;
    size.steps = static_cast<long long>(steps);
    const double every = std::max(1.0, std::round(scene.run.output_interval / dt));
    size.output_every = every >= steps ? std::max(1LL, size.steps) : static_cast<long long>(every);
    size.rows = size.steps / size.output_every + 1 + (size.steps % size.output_every != 0 ? 1 : 0);
    if (double(size.rows) > kMaxRows && !limits.allow_large)
        throw Error(where + "run.output_interval = " + g(scene.run.output_interval) + " s over run.duration = " +
                    g(scene.run.duration) + " s at dt = " + g(dt) + " s is " + g(double(size.rows)) +
                    " trajectory rows, beyond the limit of " + g(kMaxRows) +
                    " (--allow-large lifts it: 1e8 rows are tens of GB of CSV)");
    return size;
}

double machine_memory() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    if (pages > 0 && page > 0) return double(pages) * double(page);
    std::ifstream in("/proc/meminfo");
    for (std::string line; std::getline(in, line);) {
        std::istringstream ls(line);
        std::string key;
        double kib = 0.0;
        if (ls >> key >> kib && key == "MemTotal:") return kib * 1024.0;
    }
    return 0.0;
}

double memory_budget(const RunLimits& limits) {
    if (limits.memory_budget > 0.0) return limits.memory_budget;
    const double ram = machine_memory();
    return ram > 0.0 ? 0.5 * ram : 4.0 * 1024 * 1024 * 1024;   // unknown machine: 4 GiB
}

std::string bytes_text(double bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    int u = 0;
    while (bytes >= 1024.0 && u < 6) bytes /= 1024.0, ++u;
    return g(bytes) + " " + units[u];
}

}  // namespace cairn
