#include "scene_compare/variants.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>

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

std::string long_run_note(const Scene& scene, const std::vector<validation::Variant>& variants) {
    if (std::none_of(variants.begin(), variants.end(), [](const auto& v) { return v.backend == "siconos"; })) return "";
    const double free_blocks = double(std::count_if(scene.blocks.begin(), scene.blocks.end(), [](const BlockDef& b) { return !b.fixed; }));
    double dt = scene.run.dt ? *scene.run.dt : 1e-4;   // siconos's time step: its own, or run.dt, or 1e-4 s
    const auto table = scene.backend_settings.find("siconos");
    if (table != scene.backend_settings.end()) {
        const auto own = table->second.find("time_step");
        if (own != table->second.end() && std::holds_alternative<double>(own->second.value))
            dt = std::get<double>(own->second.value);
        else if (own != table->second.end() && std::holds_alternative<long long>(own->second.value))
            dt = double(std::get<long long>(own->second.value));
    }
    if (!(dt > 0.0)) return "";
    const double seconds = 71e-3 * (free_blocks / 34.0) * (free_blocks / 34.0) * std::ceil(scene.run.duration / dt);
    if (seconds < 600.0) return "";
    std::string others;   // the chosen backends but siconos, in order
    for (const auto& v : variants)
        if (v.backend != "siconos" && others.find(v.backend) == std::string::npos) others += (others.empty() ? "" : ",") + v.backend;
    char text[400];
    std::snprintf(text, sizeof text,
                  "note: siconos's step grows as the square of the free blocks (70 to 110 times Bullet's and ODE's "
                  "at 34): %.0f free blocks over %.0f steps need about %.0f %s of one core",
                  free_blocks, std::ceil(scene.run.duration / dt), seconds < 3600.0 ? seconds / 60.0 : seconds / 3600.0,
                  seconds < 3600.0 ? "min" : "h");
    std::string note = text;
    if (!others.empty()) note += "; --backends " + others + " leaves it out";
    return note + "\n";
}

}  // namespace cairn::scene_compare
