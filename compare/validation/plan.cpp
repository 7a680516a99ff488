#include "validation/plan.hpp"

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
    const std::string kind = scene.reference ? scene.reference->kind : "";
    const bool damped = scene.contact.damping_rule != ContactDampingRule::none;
    const bool rigid_ref = kind == "slide" || kind == "stick" || kind == "rolling" || (kind == "housner" && !damped) ||
                           kind == "pushover" || kind == "arch";
    const bool penalty_ref = kind == "rest" || kind == "impact" || kind == "housner";
    std::vector<Variant> out;
    for (const auto& b : backends) {
        if (b == "dem") {
            out.push_back({"dem-rigid", b, "rigid", "rigid"});
            out.push_back({"dem-deformable", b, "rigid", "deformable"});
            continue;
        }
        if (rigid_ref) out.push_back({b + "-rigid", b, "rigid", "rigid"});
        if (penalty_ref && b != "siconos") out.push_back({b + "-matched", b, "matched", "rigid"});   // siconos: rigid only
    }
    return out;
}

}  // namespace cairn::validation
