// the MuJoCo row of the capability matrix (docs/backends.md explains each entry)
#include "backend/capabilities.hpp"

#include <vector>

namespace cairn {

/// how the MuJoCo backend represents each scene feature
std::vector<FeatureSupport> mujoco_capabilities() {
    using S = Support;
    return {
        {Feature::penalty_stiffness, S::approximate,
         "matched mode: direct solref per contact from the pair's invweight, impedance 1e-3: static "
         "penetration exact, period +0.2 %"},
        {Feature::normal_damping, S::approximate, "matched mode: direct solref damping c/4 per contact (pair's reduced mass)"},
        {Feature::elastic_stick, S::none, "soft velocity-level friction: slow creep instead of a shear spring"},
        {Feature::friction_shape, S::approximate, "elliptic cone (isotropic: sliding threshold 0.999-1.0005 mu·W at 0, 30 and 45 degrees); "
         "cone = \"pyramidal\" held beyond 1.6 mu·W at 30 and 45 degrees; a sliding block rises off its base "
         "(convex model: 0.7 mm at 1 m/s, 6.5 mm at 4 m/s, rigid mode) and hops, which makes a slide depend on its "
         "direction: a 0.75 g pulse on a cube slides 0.08278 m along x or y, 0.0917 m (+10.9 %) along (0.8, 0.6)"},
        {Feature::twist_friction, S::approximate,
         "a face's friction acts at the corner contacts of the box-box collider: a square face under uniform weight holds a twist "
         "about its normal up to mu·W·a/√2, 1.85 times the mu·W·a·0.383 of friction spread over the face "
         "(measured: 1.849)"},
        {Feature::mass_damping, S::approximate, "velocities scaled by exp(-alpha·dt) after each step"},
        {Feature::stiffness_damping, S::none, "beta ignored (rigid bodies)"},
        {Feature::deformable_blocks, S::none, "refused: run with --model rigid"},
        {Feature::general_hexahedra, S::exact,
         "mesh geoms; box-mesh and mesh-mesh pairs through cairn's face-clipping collider (up to 4 points; "
         "MuJoCo 2.2.2's own gives one per pair)"},
        {Feature::held_at_rest, S::approximate,
         "soft constraints without a position term in friction (`impratio`): a 31-voussoir arch, R = 6 m, t/R = 0.15, "
         "sinks 60 µm at its crown and creeps on at 9 µm/s"},
    };
}

}  // namespace cairn
