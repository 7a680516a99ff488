#pragma once
/// Overlap of two convex hexahedra by the separating-axis test (face normals of both and the
/// cross products of their edges): exact for convex polyhedra with planar faces.

#include "geometry/hexahedron.hpp"

namespace cairn {

/// penetration depth of two convex hexahedra given by their world corners, m: the shortest
/// translation that separates them (> 0 when they overlap, <= 0 when they touch or are apart:
/// then minus the largest gap along any separating axis)
double overlap_depth(const Corners& a, const Corners& b);

/// corners of a block-frame hexahedron placed at `position` with `orientation` (world), m
Corners placed_corners(const Corners& frame, const Vec3& position, const Quat& orientation);

}  // namespace cairn
