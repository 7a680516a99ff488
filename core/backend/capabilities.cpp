#include "backend/capabilities.hpp"

namespace cairn {

const char* to_string(Support s) {
    switch (s) {
        case Support::exact: return "exact";
        case Support::approximate: return "approximate";
        case Support::none: return "none";
    }
    return "?";
}

const char* to_string(Feature f) {
    switch (f) {
        case Feature::penalty_stiffness: return "penalty stiffness kn·A";
        case Feature::normal_damping: return "normal contact damping";
        case Feature::elastic_stick: return "elastic stick before slip";
        case Feature::friction_shape: return "friction shape";
        case Feature::twist_friction: return "friction against twisting";
        case Feature::mass_damping: return "mass-proportional damping";
        case Feature::stiffness_damping: return "stiffness-proportional damping";
        case Feature::deformable_blocks: return "deformable blocks";
        case Feature::general_hexahedra: return "general convex hexahedra";
        case Feature::held_at_rest: return "a structure held at rest";
    }
    return "?";
}

}  // namespace cairn
