#pragma once
/// Contact points between two convex hexahedra (world corners, kCornerSigns order): separating
/// axes over the 12 face normals and the edge-edge cross products, then the incident face clipped
/// against the reference face (as box-box colliders do). ODE 0.16's convex-convex collider gives
/// one point per face-on-face pair and a zero normal for exactly touching faces, MuJoCo 2.2.2's
/// mesh collider one point per pair: both backends use this one for every pair with a general
/// hexahedron.

#include <vector>

#include "geometry/hexahedron.hpp"

namespace cairn {

/// one contact point between hexahedra A and B
struct HexContact {
    Vec3 position = Vec3::Zero();   ///< midway between the two surfaces, world, m
    Vec3 normal = Vec3::Zero();     ///< unit, pushes A away from B (ODE: into geom 1)
    double depth = 0.0;             ///< overlap along the normal, m (≥ 0)
};

/// at most `max_points` contacts (the largest-area subset of the clipped face polygon, or one
/// edge-edge point); empty when A and B are apart
std::vector<HexContact> hexahedron_contacts(const Corners& a, const Corners& b, int max_points = 4);

}  // namespace cairn
