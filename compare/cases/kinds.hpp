#pragma once
/// The analysis of each reference kind (internal to compare/cases; use case_analysis.hpp).

#include "cases/case_analysis.hpp"

namespace cairn::cases {

/// kind "rest" (case a) and "impact" (case b): penetration/height of the reference block
CaseAnalysis analyse_drop(const Scene& scene, const std::vector<Sample>& s, ContactKind contact);
/// kinds "slide" and "stick" (case c)
CaseAnalysis analyse_friction(const Scene& scene, const std::vector<Sample>& s, ContactKind contact);
/// kind "housner" (case e)
CaseAnalysis analyse_rocking(const Scene& scene, const std::vector<Sample>& s, ContactKind contact);
/// kind "rolling" (case d)
CaseAnalysis analyse_rolling(const Scene& scene, const std::vector<Sample>& s, ContactKind contact);

/// reference curves of the same kinds
std::vector<double> drop_curve(const Scene& scene, const std::vector<double>& t);
std::vector<double> friction_curve(const Scene& scene, const std::vector<double>& t);
std::vector<double> rocking_curve(const Scene& scene, ContactKind contact, const std::vector<double>& t);

}  // namespace cairn::cases
