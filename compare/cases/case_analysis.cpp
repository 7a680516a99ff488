#include "cases/case_analysis.hpp"

#include "cases/case_kind.hpp"
#include "error.hpp"

namespace cairn::cases {

CaseAnalysis analyse_case(const Scene& scene, const std::vector<Sample>& samples, ContactKind contact) {
    if (!scene.reference) throw Error(scene.source + ": no [reference] table: nothing to validate against");
    if (samples.size() < 3) throw Error(scene.name + ": fewer than 3 samples to analyse");
    return case_kind(scene.reference->kind, scene.source).analyse(scene, samples, contact);
}

std::vector<double> reference_curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) {
    if (!scene.reference) return {};
    return case_kind(scene.reference->kind, scene.source).curve(scene, contact, t);
}

}  // namespace cairn::cases
