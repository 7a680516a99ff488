#pragma once
/// The analyses of the structure reference kinds (internal to compare/cases; use
/// case_analysis.hpp).

#include "cases/scene_stack.hpp"
#include "cases/case_analysis.hpp"

namespace cairn::cases {

/// kind "pushover": a stack under a ramped ground acceleration, judged on the a/g at which the
/// reference block's rotation passes the threshold (value `threshold`, rad, default 0.05)
CaseAnalysis analyse_pushover(const Scene& scene, const std::vector<Sample>& s, ContactKind contact);
/// the ground acceleration of the scene in g at time t (s)
double ground_multiplier(const Scene& scene, double t);

/// kind "arch": an arch under its own weight that stands (value `stands` = 1) or collapses (0),
/// judged on the settlement of the probe `crown`
CaseAnalysis analyse_arch(const Scene& scene, const std::vector<Sample>& s, ContactKind contact);

}  // namespace cairn::cases
