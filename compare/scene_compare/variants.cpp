#include "scene_compare/variants.hpp"

namespace cairn::scene_compare {

std::vector<validation::Variant> compare_variants(const Scene& scene, const std::vector<std::string>& backends,
                                                  const std::string& model) {
    std::vector<validation::Variant> all;
    if (scene.reference) {
        all = validation::variants_for(scene, backends);
    } else {
        for (const auto& b : backends) {
            if (b == "dem") {
                all.push_back({"dem-rigid", b, "rigid", "rigid"});
                all.push_back({"dem-deformable", b, "rigid", "deformable"});
            } else {
                all.push_back({b + "-rigid", b, "rigid", "rigid"});
                all.push_back({b + "-matched", b, "matched", "rigid"});
            }
        }
    }
    std::vector<validation::Variant> out;
    for (auto& v : all)
        if (model == "both" || v.model == model) out.push_back(std::move(v));
    return out;
}

}  // namespace cairn::scene_compare
