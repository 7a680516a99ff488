#pragma once
/// The torsion spring of a sub-contact of the overlap scheme (docs/dem.md, "Twist of a
/// sub-contact"): the clipped area taken as a disc of its size, its elastic-then-Coulomb shear
/// integrated over the disc. Without it a sub-contact is one shear spring at its centroid and
/// resists no spin: a corner pressed into a single cell turns freely about the normal.

#include "contact.hpp"

namespace cairn::dem {

/// What the torsion spring of one sub-contact needs from its shear update.
struct TwistInput {
    double area = 0.0;          ///< clipped contact area, m²
    double normal_force = 0.0;  ///< normal force (spring and dashpot), N
    double shear_force = 0.0;   ///< magnitude of the shear force the sub-contact carries, N
    Vec3 centroid = Vec3::Zero();  ///< the clipped area's centroid on the target plane, m
    Vec3 normal = Vec3::UnitZ();   ///< the target's outward unit normal
    Vec3 edge = Vec3::UnitX();     ///< a direction along the hitting face (not along the normal)
    bool lay = false;           ///< the anchor is laid afresh (first touch, or after release)
};

/// The law's constants the spring uses.
struct TwistLaw {
    double ks = 0.0;            ///< shear stiffness per area, N/m³
    double friction = 0.0;      ///< Coulomb μ
    double damper = 0.0;        ///< shear dashpot per area, N·s/m³
    bool slip = true;           ///< the Coulomb cap is on
};

/// polar moment of area of a disc of area a about its centre, a²/(2π), m⁴
double disc_polar_moment(double area);
/// mean lever of a uniform traction over a disc of area a about its centre, (2/3)·√(a/π), m
double disc_friction_radius(double area);

/// update the twist state of a sub-contact over a step dt (s) of the hitting block hb (face
/// hit_face) on the target tb (face target_face): the offset grows with the relative spin about
/// the normal; the moment is capped by what friction has left after the shear force, on an
/// elliptic interaction (|F|/μN)² + (|M|/(μN·r))² ≤ 1. Books its energy and dissipation in tot.
void update_twist(SubTwist& tw, const TwistInput& in, const TwistLaw& law, const Block& hb, int hit_face,
                  const Block& tb, int target_face, double dt, ContactTotals& tot);

/// the relative spin (rad/s) about the normal of the hitting block against the target, measured at
/// the pair's points of the last evaluation
double twist_spin(const SubTwist& tw, const Block& hb, const Block& tb);

/// the spring given up (no normal force, or out of contact): its energy is dissipated, less the
/// work its last moment did over the step (the start's half kick); the state is cleared
void release_twist(SubTwist& tw, const Block& hb, const Block& tb, double dt, ContactTotals& tot);

/// the twist's moment as two opposite forces ±dir·M at the pair's points (on the hitting block; the
/// target takes the opposite), spread at once or kept in `keep`; nothing where the moment is zero
void add_twist_forces(const SubTwist& tw, const Vec3& normal, std::vector<SubForce>* keep, Block& hb, Block& tb);

}  // namespace cairn::dem
