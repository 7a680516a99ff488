#pragma once
/// The boundary term of the overlap scheme's normal force: where the contact region of a hitting
/// cell ends on a constraint fixed to the target (a target face's edge, another side's plane)
/// with depth, the stored energy U = ½kn∫d² dA changes as the face moves over that edge, and the
/// force that is the gradient of U has a part along the edge (docs/dem.md, overlap scheme).

#include "contact_overlap.hpp"

namespace cairn::dem {

/// The boundary term of the energy's gradient along edge i of a clipped polygon cut by a
/// constraint g fixed to the target (a target face's edge, another side's plane): as the hitting
/// face moves, that edge moves over it and U = ½kn∫d² dA changes by the strip it sweeps. The
/// force on the hitting face is −½kn·a/|a_t − (a·n)∇d| per unit length of the edge's projection
/// times d², a = g's gradient, a_t its part along the plane, ∇d the polygon's depth slope
/// (docs/dem.md, overlap scheme); it acts on the edge's hitting points weighted by d².
struct EdgeForce {
    Vec3 force = Vec3::Zero();   ///< on the hitting face (the target takes −force), N
    Vec3 point = Vec3::Zero();   ///< where it acts: ∫p·d² ds / ∫d² ds over the edge's hitting points p, m
    double d2 = 0.0;             ///< ∫d² ds along the edge's projection on the target plane, m³
    double offset_gradient = 0.0;///< dU/db: U's change per unit of the constraint's offset b, N
};
/// the edge force of edge i of `poly` (target plane through c, unit normal n; penalty kn, N/m³;
/// `slope` the polygon's OverlapIntegrals::slope, the gradient of its depth behind that plane);
/// `depth`: the penetration when it is not the depth behind that plane (the region beyond a capped
/// cut, contact_overlap_beyond.hpp), m; the polygon is still projected on that plane
EdgeForce edge_force(const ClipPolygon& poly, int i, const Vec3& c, const Vec3& n, const Affine& g,
                     const Vec3& slope, double kn, const Affine* depth = nullptr);

}  // namespace cairn::dem
