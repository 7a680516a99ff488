#pragma once
/// The face-to-face contacts of an assembly of convex hexahedral blocks in a given configuration,
/// for limit analysis (block_limit_analysis.hpp): two faces touch where they are coplanar with
/// opposite outward normals and their quads overlap with positive area; the contact is the
/// overlap polygon (one quad clipped by the other, Sutherland–Hodgman in their plane). A rigid
/// no-tension joint's statics is exactly that of forces at the polygon's vertices. Edge-to-face and
/// corner-to-face contacts are not found.

#include <vector>

#include "geometry/hexahedron.hpp"

namespace cairn::oracle {

/// one contact interface between blocks `first` and `second`
struct BlockInterface {
    int first = 0;                   ///< block index; the contact force on it is +f
    int second = 0;                  ///< block index (> first); the force on it is −f, at the same point
    Vec3 normal = Vec3::Zero();      ///< unit, world: from `second` into `first` (compression pushes `first` along it)
    std::vector<Vec3> polygon;       ///< vertices of the contact area, world, m (convex, ≥ 3)
    double area = 0.0;               ///< m²
};

/// the interfaces of the blocks given by their world corners, pairs of two fixed blocks left out.
/// Faces count as coplanar when their normals are anti-parallel within 1e-6 rad and every corner
/// of each lies within `gap` (m) of the other's plane; overlaps below 1e-9 of the smaller face's
/// area are dropped. Pairs are pruned by bounding boxes inflated by `gap`.
std::vector<BlockInterface> find_interfaces(const std::vector<Corners>& corners, const std::vector<bool>& fixed,
                                            double gap);

/// the convex polygon (world, m, in the plane of unit `normal`) with every edge moved `inset` (m)
/// inward: the part of a joint a compliant contact still carries at its edges (a hinge inset);
/// a polygon narrower than twice the inset becomes its centre
std::vector<Vec3> inset_polygon(const std::vector<Vec3>& polygon, const Vec3& normal, double inset);

}  // namespace cairn::oracle
