// the ODE row of the capability matrix (docs/backends.md explains each entry)
#include "backend/capabilities.hpp"

#include <vector>

namespace cairn {

/// how the ODE backend represents each scene feature
std::vector<FeatureSupport> ode_capabilities() {
    using S = Support;
    return {
        {"penalty stiffness kn·A", S::approximate,
         "matched mode: kn·A/4 per contact (A = smaller bottom face of the pair) as soft ERP/CFM; "
         "rigid mode: near-rigid contact"},
        {"normal contact damping", S::approximate, "matched mode: dashpot per contact (c/4); rigid: none"},
        {"elastic stick before slip", S::none, "velocity-level Coulomb friction: no shear spring"},
        {"friction shape", S::approximate, "dContactApprox1: mu·N per direction, two directions (pyramid), the first along the trial sliding "
         "velocity (dContactFDir1): sliding threshold 1.002 mu·W at 0, 30 and 45 degrees (1.158 and 1.416 "
         "at 30 and 45 degrees without it)"},
        {"mass-proportional damping", S::approximate, "velocities scaled by exp(-alpha·dt) after each step"},
        {"stiffness-proportional damping", S::none, "beta ignored (rigid bodies)"},
        {"deformable blocks", S::none, "refused: run with --model rigid"},
        {"general convex hexahedra", S::exact, "cairn's face-clipping collider (up to 4 points per pair; ODE's convex-convex gave one, and a zero "
         "normal on touching faces); dCreateConvex only for the broad phase"},
    };
}

}  // namespace cairn
