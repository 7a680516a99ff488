// the MuJoCo row of the capability matrix (docs/backends.md explains each entry)
#include "backend/capabilities.hpp"

#include <vector>

namespace cairn {

/// how the MuJoCo backend represents each scene feature
std::vector<FeatureSupport> mujoco_capabilities() {
    using S = Support;
    return {
        {"penalty stiffness kn·A", S::approximate,
         "matched mode: mass-normalised solref calibrated so the static penetration is mg/(kn·A); "
         "the contact frequency is not matched"},
        {"normal contact damping", S::approximate, "matched mode: solref damping as a ratio of MuJoCo's own spring"},
        {"elastic stick before slip", S::none, "soft velocity-level friction: slow creep instead of a shear spring"},
        {"friction shape", S::approximate, "pyramidal cone by default (setting cone = \"elliptic\" for a cone)"},
        {"mass-proportional damping", S::approximate, "velocities scaled by exp(-alpha·dt) after each step"},
        {"stiffness-proportional damping", S::none, "beta ignored (rigid bodies)"},
        {"deformable blocks", S::none, "refused: run with --model rigid"},
        {"general convex hexahedra", S::approximate, "mesh geoms; MuJoCo 2.2.2 gives one contact per mesh pair"},
    };
}

}  // namespace cairn
