#pragma once
/// A block of the in-house engine: its nodes, boundary faces, hitting points and motion.

#include <array>
#include <string>
#include <vector>

#include "face.hpp"
#include "geometry/hexahedron.hpp"
#include "rigid_body.hpp"

namespace cairn::dem {

/// One block. Rigid blocks have the 8 corners as nodes and the 6 sides as faces.
struct Block {
    std::string name;
    bool fixed = false;                       ///< no degrees of freedom
    RigidBody body;                           ///< pose and momenta (fixed: pose only)
    Vec3 com_in_frame = Vec3::Zero();         ///< centre of mass in the block frame, m
    double volume = 0.0;                      ///< m³
    double r_max = 0.0;                       ///< largest distance of a corner from the centre, m
    double min_edge = 0.0;                    ///< shortest edge length, m

    std::vector<Vec3> local;                  ///< nodes relative to the centre, block axes, m
    std::vector<Vec3> x;                      ///< nodes, world, m
    std::vector<Vec3> v;                      ///< node velocities, world, m/s
    std::vector<Vec3> f;                      ///< node forces of the current step, N
    std::vector<std::array<int, 4>> faces;    ///< boundary faces as node indices (outward order)
    std::vector<std::vector<HitPoint>> hits;  ///< hitting points of each face
    std::vector<double> face_area;            ///< m², at t = 0

    Vec3 x_at_refresh = Vec3::Zero();         ///< centre at the last contact refresh, m
    Quat q_at_refresh = Quat::Identity();     ///< orientation at the last contact refresh

    /// the 4 world corner points of face k
    Quad face_quad(int k) const { return {x[faces[k][0]], x[faces[k][1]], x[faces[k][2]], x[faces[k][3]]}; }
    /// world position of a block-frame point, m
    Vec3 world_point(const Vec3& frame_point) const { return body.x + body.q * (frame_point - com_in_frame); }
    /// set node positions and velocities from the rigid pose and momenta
    void update_nodes();
    /// bound on how far any point moved since the last refresh, m
    double motion_since_refresh() const;
    /// axis-aligned bounds of the nodes
    Aabb bounds() const;
};

}  // namespace cairn::dem
