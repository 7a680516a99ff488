#include "scene/reference_kinds.hpp"

namespace cairn {

const std::vector<ReferenceKind>& reference_kinds() {
    static const std::vector<ReferenceKind> kinds = {
        {"rest", {}},                                          // block at rest on its support
        {"impact", {"gap"}},                                   // drop through gap (m)
        {"slide", {"force"}},                                  // horizontal force (N), slides
        {"stick", {"force"}},                                  // horizontal force (N), holds
        {"incline", {"angle"}},                                // plane angle (rad)
        {"newmark", {}},                                       // loads along a plane base, level or tilted: Newmark's block
        {"rolling", {"slope"}},                                // slope angle (rad)
        {"housner", {"theta0", "axis_x", "axis_y", "axis_z", "impacts"}}, // release tilt (rad), rocking axis, impacts judged on a calibrated damped contact
        {"winkler_rocking", {"theta0", "axis_x", "axis_y", "axis_z"}},   // release tilt (rad), rocking axis: on a Winkler base of modulus kn
        {"ground_rocking", {}},                                 // one block rocking under its ground motion: Housner's equation, or dem's Winkler base
        {"pushover", {"threshold"}},                           // ramped ground motion: rotation (rad) judged
        {"arch", {"stands", "thickness"}},                     // 1 stands / 0 collapses, thickness (m)
    };
    return kinds;
}

const ReferenceKind* find_reference_kind(const std::string& name) {
    for (const auto& k : reference_kinds())
        if (k.name == name) return &k;
    return nullptr;
}

}  // namespace cairn
