#pragma once
/// A block of the in-house engine: its mesh (rigid blocks: one element), boundary faces with
/// their hitting points, nodal positions, velocities and forces, and either a rigid body or a
/// deformable body that moves the nodes.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "dem/deformable/deformable_body.hpp"
#include "face.hpp"
#include "geometry/hexahedron.hpp"
#include "mesh.hpp"
#include "rigid_body.hpp"

namespace cairn::dem {

/// One block.
struct Block {
    std::string name;
    bool fixed = false;                       ///< no degrees of freedom
    RigidBody body;                           ///< rigid: the state; deformable: best-fit pose, mass, inertia
    std::shared_ptr<DeformableBody> deformable;  ///< set for deformable blocks
    Vec3 com_in_frame = Vec3::Zero();         ///< centre of mass in the block frame, m
    double volume = 0.0;                      ///< m³
    double r_max = 0.0;                       ///< largest distance of a corner from the centre, m
    double min_edge = 0.0;                    ///< shortest edge of the block, m
    /// rigid, every side planar and square to its neighbours: a side's edges lie on their planes
    bool box = false;

    Mesh mesh;                                ///< nodes, elements, boundary faces and sides
    std::vector<Vec3> local;                  ///< rigid: nodes relative to the centre, block axes, m
    std::vector<Vec3> x;                      ///< nodes, world, m
    std::vector<Vec3> v;                      ///< node velocities, world, m/s
    std::vector<Vec3> f;                      ///< node forces of the current step, N
    std::vector<std::vector<HitPoint>> hits;  ///< hitting points of each boundary face
    std::array<double, 6> side_area{};        ///< area of each side at t = 0, m²

    /// rigid: the angular velocity the nodes' velocities were set with (update_nodes), world, rad/s
    Vec3 spin = Vec3::Zero();
    Mat3 rotation = Mat3::Identity();         ///< rigid: the pose's rotation the nodes were set from (update_nodes)
    std::array<Vec3, 6> side_normal_local{};  ///< rigid: each side's outward unit normal at its centre, block axes
    std::array<Vec3, 6> side_centre_local{};  ///< rigid: each side's centre relative to the centre, block axes, m
    Mat3 corner_inverse = Mat3::Identity();   ///< rigid: inverse of the corner frame node_weights uses (set by update_nodes), 1/m
    Vec3 x_at_refresh = Vec3::Zero();         ///< centre at the last contact refresh, m
    Quat q_at_refresh = Quat::Identity();     ///< orientation at the last contact refresh

    /// the 4 world corner points of boundary face k
    Quad face_quad(int k) const {
        const auto& fc = mesh.faces[k];
        return {x[fc[0]], x[fc[1]], x[fc[2]], x[fc[3]]};
    }
    /// the 4 world corner points of side s (0-5)
    Quad side_quad(int s) const {
        const auto& c = mesh.side_corners[s];
        return {x[c[0]], x[c[1]], x[c[2]], x[c[3]]};
    }
    /// the boundary face of side s that contains side natural coordinates xi
    int face_at(int s, const Vec2& xi) const;
    /// world position of a block-frame point (rigid pose; deformable: interpolated), m
    Vec3 world_point(const Vec3& frame_point) const;
    /// rigid: set node positions and velocities from the pose and momenta;
    /// deformable: set the best-fit pose from the nodes
    void update_nodes();
    /// angle the block's frame turned through since the last refresh, rad
    double turn_since_refresh() const;
    /// axis-aligned bounds of the nodes
    Aabb bounds() const;
};

}  // namespace cairn::dem
