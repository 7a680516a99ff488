// the Siconos row of the capability matrix (docs/backends.md explains each entry)
#include "backend/capabilities.hpp"

#include <vector>

namespace cairn {

/// how the Siconos backend represents each scene feature
std::vector<FeatureSupport> siconos_capabilities() {
    using S = Support;
    return {
        {Feature::penalty_stiffness, S::none,
         "rigid unilateral contact (Signorini condition at velocity level, Moreau–Jean): no normal spring, no "
         "matched mode"},
        {Feature::normal_damping, S::none, "Newton impact law with restitution contact.restitution instead"},
        {Feature::elastic_stick, S::none, "Coulomb friction as a complementarity (rigid stick): no shear spring"},
        {Feature::friction_shape, S::exact, "the exact Coulomb cone per contact point (3-D friction-contact problem), no "
         "facets"},
        {Feature::twist_friction, S::approximate,
         "a face's friction acts at the four corner contact points: a square face under uniform weight holds a twist "
         "about its normal up to mu·W·a/√2, 1.85 times the mu·W·a·0.383 of friction spread over the face "
         "(measured: 1.849)"},
        {Feature::mass_damping, S::approximate,
         "forces -alpha·m·v and -alpha·I·omega from the start-of-step velocities"},
        {Feature::stiffness_damping, S::none, "beta ignored (rigid bodies)"},
        {Feature::deformable_blocks, S::none, "refused: run with --model rigid"},
        {Feature::general_hexahedra, S::exact,
         "cairn's face-clipping collider (up to 4 points per pair) handed to Siconos as point contacts"},
        {Feature::held_at_rest, S::exact,
         "the friction-contact problem solved to its `tolerance` each step: a 25-voussoir arch at R = 5 m stops settling "
         "(0.3 µm in the second half of 4 s)"},
    };
}

}  // namespace cairn
