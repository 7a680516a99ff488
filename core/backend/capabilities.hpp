#pragma once
/// What a backend can represent of a scene: exactly, approximately (and how), or not at all.

#include <string>
#include <vector>

namespace cairn {

enum class Support { exact, approximate, none };

/// A feature of a scene a backend may represent: the rows of the capability matrix.
enum class Feature {
    penalty_stiffness,   ///< "penalty stiffness kn·A"
    normal_damping,   ///< "normal contact damping"
    elastic_stick,   ///< "elastic stick before slip"
    friction_shape,   ///< "friction shape"
    twist_friction,   ///< "friction against twisting"
    mass_damping,   ///< "mass-proportional damping"
    stiffness_damping,   ///< "stiffness-proportional damping"
    deformable_blocks,   ///< "deformable blocks"
    general_hexahedra,   ///< "general convex hexahedra"
    held_at_rest,   ///< "a structure held at rest"
};

/// One scene feature and how a backend represents it.
struct FeatureSupport {
    Feature feature = Feature::penalty_stiffness;
    Support support = Support::none;
    std::string how;       ///< for approximate/none: what is done instead
};

const char* to_string(Support s);

/// the feature's row name, e.g. "elastic stick before slip"
const char* to_string(Feature f);

}  // namespace cairn
