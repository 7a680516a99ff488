#include "scene/reference_kinds.hpp"

namespace cairn {

const std::vector<ReferenceKind>& reference_kinds() {
    static const std::vector<ReferenceKind> kinds = {
        {"rest", {}},                                          // block at rest on its support
        {"impact", {"gap"}},                                   // drop through gap (m)
        {"slide", {"force"}},                                  // horizontal force (N), slides
        {"stick", {"force"}},                                  // horizontal force (N), holds
        {"incline", {"angle"}},                                // plane angle (rad)
        {"rolling", {"slope"}},                                // slope angle (rad)
        {"housner", {"theta0", "axis_x", "axis_y", "axis_z", "impacts"}}, // release tilt (rad), rocking axis, impacts judged on a calibrated damped contact
    };
    return kinds;
}

const ReferenceKind* find_reference_kind(const std::string& name) {
    for (const auto& k : reference_kinds())
        if (k.name == name) return &k;
    return nullptr;
}

}  // namespace cairn
