#pragma once
/// Point contacts of the siconos backend from cairn's own block geometry: every pair of blocks
/// closer than a margin gets the vertex–face, face–face and edge–edge points of
/// hexahedron_contacts, with the true gap (positive apart, negative overlapping) so that the
/// Moreau–Jean scheme can close a contact before the blocks meet.

#include <vector>

#include "geometry/hexahedron.hpp"

namespace cairn {

/// one contact point between blocks a and b
struct GapContact {
    int a = 0;                       ///< index of the block pushed along +normal (free)
    int b = 0;                       ///< index of the other block (may be fixed)
    Vec3 on_a = Vec3::Zero();        ///< point of a's surface, world, m
    Vec3 on_b = Vec3::Zero();        ///< point of b's surface facing it, world, m
    Vec3 normal = Vec3::Zero();      ///< unit, pushes a away from b
    double gap = 0.0;                ///< (on_a − on_b)·normal, m: > 0 apart, < 0 overlapping
};

/// the corners of a hexahedron with every face plane moved out by `margin` (m)
Corners inflated_corners(const Corners& c, double margin);

/// contact points of two hexahedra whose gap is below `margin` (m): the normal from the pair
/// inflated by the margin, then the points of the real pair with a moved by −margin along it,
/// whose depth d gives the real gap margin − d (a translation along the normal changes no
/// lateral position); at most `max_points`
std::vector<GapContact> gap_contacts(const Corners& a, const Corners& b, double margin, int max_points = 4);

/// block pairs (i < j by position in `corners`) whose bounding boxes, grown by `margin`, overlap,
/// leaving out pairs where both are fixed; sorted, so the same input gives the same list
std::vector<std::pair<int, int>> near_pairs(const std::vector<Corners>& corners, const std::vector<bool>& fixed,
                                            double margin);

}  // namespace cairn
