#pragma once
/// Why a validation metric misses, when the cause is a known limitation of the engine that ran it:
/// the report lists every miss with its cause and, where it can be computed, its predicted size.

#include <string>

#include "metrics/metric.hpp"
#include "scene/scene.hpp"
#include "validation/plan.hpp"

namespace cairn::report {

/// A missed metric's cause.
struct MissCause {
    bool known = false;   ///< false: no known limitation explains it (an engine or reference defect)
    std::string text;     ///< the cause, with its predicted size where one is computed
};

/// the cause of `metric` missing on `variant` run with time step `dt` (s) on `scene`
MissCause miss_cause(const Scene& scene, const validation::Variant& variant, const metrics::Metric& metric, double dt);

/// the rebound-height ratio of a block dropped through `gap` (m) onto a spring of angular frequency
/// `omega` (rad/s) with a dashpot of `zeta` times critical, the force never pulling, as an engine
/// integrates it implicitly (the erp/cfm form of Bullet's and ODE's matched contact: the force uses
/// the end-of-step position and velocity, so each undamped step in contact keeps 1/(1 + (ω h)²) of
/// the oscillation energy); found by stepping that 1-DOF contact with gravity `g` (m/s²) at `dt`
/// (s); NaN past 10⁸ steps
double implicit_spring_rebound(double omega, double zeta, double dt, double gap, double g);

}  // namespace cairn::report
