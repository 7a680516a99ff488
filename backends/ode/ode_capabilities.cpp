// the ODE row of the capability matrix (docs/backends.md explains each entry)
#include "backend/capabilities.hpp"

#include <vector>

namespace cairn {

/// how the ODE backend represents each scene feature
std::vector<FeatureSupport> ode_capabilities() {
    using S = Support;
    return {
        {Feature::penalty_stiffness, S::approximate,
         "matched mode: kn·A/4 per contact (A = the smaller of the two faces that bear the contact) as soft ERP/CFM; "
         "rigid mode: near-rigid contact"},
        {Feature::normal_damping, S::approximate, "matched mode: dashpot per contact (c/4); rigid: none"},
        {Feature::elastic_stick, S::none, "velocity-level Coulomb friction: no shear spring"},
        {Feature::friction_shape, S::approximate, "dContactApprox1: mu·N per direction, two directions (pyramid), the first along the trial sliding "
         "velocity (dContactFDir1): sliding threshold 1.002 mu·W at 0, 30 and 45 degrees (1.158 and 1.416 "
         "at 30 and 45 degrees without it)"},
        {Feature::twist_friction, S::approximate,
         "a face's friction acts at the four corner contacts of the box-box collider: a square face under uniform weight holds a twist "
         "about its normal up to mu·W·a/√2, 1.85 times the mu·W·a·0.383 of friction spread over the face "
         "(measured: 1.849)"},
        {Feature::mass_damping, S::approximate, "velocities scaled by exp(-alpha·dt) after each step"},
        {Feature::stiffness_damping, S::none, "beta ignored (rigid bodies)"},
        {Feature::deformable_blocks, S::none, "refused: run with --model rigid"},
        {Feature::general_hexahedra, S::exact, "cairn's face-clipping collider (up to 4 points per pair; ODE's convex-convex gave one, and a zero "
         "normal on touching faces); dCreateConvex only for the broad phase"},
        {Feature::held_at_rest, S::approximate,
         "QuickStep, an iterative solver (`iterations`, 200): a 31-voussoir arch, R = 6 m, t/R = 0.15, creeps at its crown "
         "56 µm/s; `stepper = \"step\"` holds a few stacked blocks but drops arches of many voussoirs (docs/backends.md)"},
    };
}

}  // namespace cairn
