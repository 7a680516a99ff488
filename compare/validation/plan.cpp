#include "validation/plan.hpp"

#include "cases/case_kind.hpp"

namespace cairn::validation {

cases::ContactKind contact_kind(const Variant& v, const Scene& scene) {
    cases::ContactKind k;
    k.penalty = v.penalty();
    k.point_springs = v.backend == "dem";
    if (v.model == "deformable" && scene.reference) {
        k.deformable = true;
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

std::vector<Variant> backend_variants(const BackendInfo& b, const std::vector<std::string>& modes) {
    std::vector<Variant> out;
    if (b.contact == ContactModel::penalty) {
        out.push_back({b.name + "-rigid", b.name, "rigid", "rigid"});
        if (support_of(b, Feature::deformable_blocks) != Support::none)
            out.push_back({b.name + "-deformable", b.name, "rigid", "deformable"});
        return out;
    }
    const bool springs = support_of(b, Feature::penalty_stiffness) != Support::none;
    for (const auto& m : modes)
        if (m != "matched" || springs) out.push_back({b.name + "-" + m, b.name, m, "rigid"});
    return out;
}

std::vector<Variant> variants_for(const Scene& scene, const std::vector<BackendInfo>& backends) {
    // the reference kind decides which engine contact modes it can judge; an unknown kind is an
    // error here rather than a case run on dem alone
    std::vector<std::string> modes;
    if (scene.reference) {
        const auto& kind = cases::case_kind(scene.reference->kind, scene.source);
        kind.check(scene);
        modes = kind.contact_modes(scene);
    }
    std::vector<Variant> out;
    for (const auto& b : backends)
        for (auto& v : backend_variants(b, modes)) out.push_back(std::move(v));
    return out;
}

}  // namespace cairn::validation
