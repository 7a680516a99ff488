#pragma once
/// Scene blocks as rigid bodies for the reference engines: mass properties, the centre-of-mass
/// frame an engine simulates, and conversions back to cairn's block frame.

#include <array>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "geometry/hexahedron.hpp"
#include "scene/scene.hpp"

namespace cairn {

/// One scene block seen as a rigid body.
struct RigidBlock {
    int index = 0;                        ///< index into Scene::blocks
    std::string name;                     ///< block name
    bool fixed = false;                   ///< no degrees of freedom
    bool is_box = false;                  ///< true: an axis-aligned box in its block frame
    Corners corners;                      ///< corners in the block frame, m
    double mass = 0.0;                    ///< kg
    Vec3 com = Vec3::Zero();              ///< centre of mass in the block frame, m
    Mat3 inertia = Mat3::Zero();          ///< inertia about the centre of mass, block axes, kg·m²
    Mat3 principal = Mat3::Identity();    ///< columns: principal axes in block axes (rotation)
    Vec3 moments = Vec3::Zero();          ///< principal moments of inertia, kg·m²
    Vec3 half_extents = Vec3::Zero();     ///< box half extents along the block axes, m (boxes only)
    std::array<Vec3, 6> face_normals{};   ///< outward unit normal of each face, block axes
    std::array<double, 6> face_areas{};   ///< area of each face, m²
    Vec3 com_world = Vec3::Zero();        ///< centre of mass at t = 0, world, m
    Quat orientation = Quat::Identity();  ///< rotation block frame → world at t = 0
};

/// every scene block as a rigid body, in scene order; throws cairn::Error for a deformable block
/// ("backend <backend> cannot represent deformable block ...") or a bad material index
std::vector<RigidBlock> rigid_blocks(const Scene& scene, const std::string& backend);

/// world position of a block-frame point given the block's centre of mass (world) and orientation
Vec3 block_point_world(const RigidBlock& b, const Vec3& com_world, const Quat& q, const Vec3& point);

/// kinetic energy ½ m v² + ½ ωᵀ I_world ω of a block, J
double kinetic_energy(const RigidBlock& b, const Quat& q, const Vec3& v, const Vec3& w);

/// gravity potential −m g·x of a block whose centre of mass is at `com_world`, J
double potential_energy(const RigidBlock& b, const Vec3& gravity, const Vec3& com_world);

/// append a free block's state to a sample, adding its kinetic and gravitational energy
void add_block_state(Sample& sample, const RigidBlock& b, const BlockState& state, const Vec3& gravity);

/// per-point penalty spring of the matched contact mode
struct PointSpring {
    double stiffness = 0.0;   ///< N/m per contact point
    double damping = 0.0;     ///< N·s/m per contact point
};

/// area of the face of block `b` (orientation `q`, block frame → world) that bears a contact whose
/// normal, pointing out of `b`, is `out` (world): the face whose outward normal is most aligned
/// with `out`; faces aligned within 1e-9 of the best are a tie and the smallest of them counts, m²
double bearing_area(const RigidBlock& b, const Quat& q, const Vec3& out);

/// the scene's face spring kn·A and its contact damping, split over `points` contact points, for a
/// contact of blocks `a` and `b` (orientations `qa`, `qb`, block frame → world) whose normal `n`
/// (world, unit) points from a towards b: A is the smaller of the two blocks' bearing areas
PointSpring matched_point_spring(const Scene& scene, const RigidBlock& a, const Quat& qa, const RigidBlock& b,
                                 const Quat& qb, const Vec3& n, int points = 4);

/// the stiffest angular frequency (rad/s) of the scene's matched springs: each free block on any
/// of its faces with kn·A/4 and ks·A/4 at the face's corners (MuJoCo's four contacts a face),
/// and for two or more free blocks the two stiffest pressed together (their ω² summed, as dem's
/// critical step bounds a pair); 0 without a free block
double matched_spring_omega(const Scene& scene, const std::vector<RigidBlock>& blocks);

/// the notes every velocity-level rigid-body engine adds for a scene: what it ignores (ks, β)
/// and what its energy columns hold
std::vector<std::string> rigid_engine_notes(const Scene& scene);

}  // namespace cairn
