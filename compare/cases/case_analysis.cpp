#include "cases/case_analysis.hpp"

#include "cases/kinds.hpp"
#include "cases/structure_kinds.hpp"
#include "error.hpp"

namespace cairn::cases {

CaseAnalysis analyse_case(const Scene& scene, const std::vector<Sample>& samples, ContactKind contact) {
    if (!scene.reference) throw Error(scene.source + ": no [reference] table: nothing to validate against");
    if (samples.size() < 3) throw Error(scene.name + ": fewer than 3 samples to analyse");
    const std::string& k = scene.reference->kind;
    if (k == "rest" || k == "impact") return analyse_drop(scene, samples, contact);
    if (k == "slide" || k == "stick") return analyse_friction(scene, samples, contact);
    if (k == "housner") return analyse_rocking(scene, samples, contact);
    if (k == "rolling") return analyse_rolling(scene, samples, contact);
    if (k == "pushover") return analyse_pushover(scene, samples, contact);
    if (k == "arch") return analyse_arch(scene, samples, contact);
    throw Error(scene.source + ": reference kind '" + k + "' has no validation metrics");
}

std::vector<double> reference_curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) {
    if (!scene.reference) return {};
    const std::string& k = scene.reference->kind;
    if (k == "rest" || k == "impact") return drop_curve(scene, t);
    if (k == "slide" || k == "stick") return friction_curve(scene, t);
    if (k == "housner") return rocking_curve(scene, contact, t);
    return {};
}

}  // namespace cairn::cases
