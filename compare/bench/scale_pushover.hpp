#pragma once
/// The second accuracy measure of `cairn bench scale`: the out-of-plane pushover multiplier of the
/// free-standing running-bond wall of scenarios/structures/wall_pushover (18 bricks: 4 courses, t/H
/// = 0.25 plus the ramp's lag), and each backend's cost to reach it within 2 %.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "scene/scene_io.hpp"

namespace cairn::bench {

/// One setting of one backend on the pushover wall.
struct PushoverPoint {
    std::string backend;
    std::string setting;        ///< the overrides, e.g. "run.dt=1e-3 backends.ode.stepper=step"
    double dt = 0.0;            ///< s
    double multiplier = 0.0;    ///< a/g when the top brick turns 0.05 rad (NaN: never)
    double reference = 0.0;     ///< the rigid wall's a/g at that rotation under the ramp
    double error = 0.0;         ///< multiplier / reference − 1 (NaN: never turned)
    double cost = 0.0;          ///< wall seconds of the stepping loop per simulated second
    std::string status;         ///< "completed", "unstable: …", "refused: …"
};

/// the settings tried per backend, cheapest first: dem dt auto at run.dt_safety 0.4, 0.2, 0.1 of
/// its critical step (its paper contact, the scene's); the engines in their rigid contact at dt
/// 1e-3, 3e-4, 1e-4 s (ODE with its exact dWorldStep, which holds a stack: docs/backends.md)
std::vector<std::vector<Override>> pushover_settings(const std::string& backend);

/// run each backend at its settings in order until one reaches the reference within `tolerance`
/// (relative), on the scene file `path` (a pushover reference)
std::vector<PushoverPoint> scale_pushover(const std::string& path, const std::vector<std::string>& backends,
                                          double tolerance,
                                          const std::function<std::unique_ptr<Backend>(const std::string&)>& make,
                                          bool quiet);

/// per backend: the cheapest completed point within `tolerance` (nullptr: none)
const PushoverPoint* cheapest_reaching(const std::vector<PushoverPoint>& points, const std::string& backend,
                                       double tolerance);

/// scale_pushover.csv text and its parse
std::string pushover_csv(const std::vector<PushoverPoint>& points);
std::vector<PushoverPoint> parse_pushover_csv(const std::string& text);

}  // namespace cairn::bench
