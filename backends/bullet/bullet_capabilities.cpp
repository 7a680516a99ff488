// the Bullet row of the capability matrix (docs/backends.md explains each entry)
#include "backend/capabilities.hpp"

#include <vector>

namespace cairn {

/// how the Bullet backend represents each scene feature
std::vector<FeatureSupport> bullet_capabilities() {
    using S = Support;
    return {
        {Feature::penalty_stiffness, S::approximate,
         "matched mode: kn·A/4 per manifold point (A = the smaller of the two faces that bear the contact) as ERP/CFM; "
         "rigid mode: near-rigid contact"},
        {Feature::normal_damping, S::approximate, "matched mode: dashpot per manifold point (c/4); rigid: none"},
        {Feature::elastic_stick, S::none, "velocity-level Coulomb friction: no shear spring"},
        {Feature::friction_shape, S::approximate, "two friction directions clamped separately per point (box), the first along the sliding "
         "velocity: sliding threshold 1.002 mu·W at 0, 30 and 45 degrees"},
        {Feature::twist_friction, S::approximate,
         "a face's friction acts at the four corner points of its contact manifold: a square face under uniform weight holds a twist "
         "about its normal up to mu·W·a/√2, 1.85 times the mu·W·a·0.383 of friction spread over the face "
         "(measured: 1.849)"},
        {Feature::mass_damping, S::approximate, "body damping 1-exp(-alpha), applied after each step"},
        {Feature::stiffness_damping, S::none, "beta ignored (rigid bodies)"},
        {Feature::deformable_blocks, S::none, "refused: run with --model rigid"},
        {Feature::general_hexahedra, S::exact, "btConvexHullShape with polyhedral contact clipping"},
        {Feature::held_at_rest, S::approximate,
         "an iterative solver (`iterations`, 50): a stack or arch held by friction creeps; a 31-voussoir arch, R = 6 m, "
         "t/R = 0.15: crown 1.9 mm/s at 50 iterations, 0.35 at 200, 0.10 at 1000"},
    };
}

}  // namespace cairn
