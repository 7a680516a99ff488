#include "scene_compare/variants.hpp"

namespace cairn::scene_compare {

std::vector<validation::Variant> compare_variants(const Scene& scene, const std::vector<BackendInfo>& backends,
                                                  const std::string& model) {
    std::vector<validation::Variant> all;
    if (scene.reference) {
        all = validation::variants_for(scene, backends);
    } else {
        for (const auto& b : backends)
            for (auto& v : validation::backend_variants(b, {"rigid", "matched"})) all.push_back(std::move(v));
    }
    std::vector<validation::Variant> out;
    for (auto& v : all)
        if (model == "both" || v.model == model) out.push_back(std::move(v));
    return out;
}

}  // namespace cairn::scene_compare
