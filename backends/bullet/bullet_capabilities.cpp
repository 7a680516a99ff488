// the Bullet row of the capability matrix (docs/backends.md explains each entry)
#include "backend/capabilities.hpp"

#include <vector>

namespace cairn {

/// how the Bullet backend represents each scene feature
std::vector<FeatureSupport> bullet_capabilities() {
    using S = Support;
    return {
        {"penalty stiffness kn·A", S::approximate,
         "matched mode: kn·A/4 per manifold point (A = smaller bottom face of the pair) as ERP/CFM; "
         "rigid mode: near-rigid contact"},
        {"normal contact damping", S::approximate, "matched mode: dashpot per manifold point (c/4); rigid: none"},
        {"elastic stick before slip", S::none, "velocity-level Coulomb friction: no shear spring"},
        {"friction shape", S::approximate, "two friction directions clamped separately per point (box), the first along the sliding "
         "velocity: sliding threshold 1.002 mu·W at 0, 30 and 45 degrees"},
        {"mass-proportional damping", S::approximate, "body damping 1-exp(-alpha), applied after each step"},
        {"stiffness-proportional damping", S::none, "beta ignored (rigid bodies)"},
        {"deformable blocks", S::none, "refused: run with --model rigid"},
        {"general convex hexahedra", S::exact, "btConvexHullShape with polyhedral contact clipping"},
    };
}

}  // namespace cairn
