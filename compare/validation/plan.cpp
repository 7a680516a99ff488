#include "validation/plan.hpp"

#include "cases/case_kind.hpp"

namespace cairn::validation {

cases::ContactKind contact_kind(const Variant& v, const Scene& scene) {
    cases::ContactKind k;
    k.penalty = v.penalty();
    k.point_springs = v.backend == "dem";
    if (v.model == "deformable" && scene.reference) {
        k.divisions = scene.blocks.at(scene.reference->block).mesh.divisions;
    }
    return k;
}

const std::vector<std::string>& paper_cases() {
    static const std::vector<std::string> names = {
        "stability", "impact", "impact_damped", "friction_slide", "friction_stick", "friction_stick_base", "rolling",
        "rocking", "rocking_damped_02", "rocking_damped_04", "rocking_slender", "rocking_housner"};
    return names;
}

std::vector<Variant> variants_for(const Scene& scene, const std::vector<std::string>& backends) {
    // the reference kind decides which engine contact modes it can judge; an unknown kind is an
    // error here rather than a case run on dem alone
    std::vector<std::string> modes;
    if (scene.reference) modes = cases::case_kind(scene.reference->kind, scene.source).contact_modes(scene);
    std::vector<Variant> out;
    for (const auto& b : backends) {
        if (b == "dem") {
            out.push_back({"dem-rigid", b, "rigid", "rigid"});
            out.push_back({"dem-deformable", b, "rigid", "deformable"});
            continue;
        }
        for (const auto& m : modes)
            if (m != "matched" || b != "siconos") out.push_back({b + "-" + m, b, m, "rigid"});   // siconos: rigid only
    }
    return out;
}

}  // namespace cairn::validation
