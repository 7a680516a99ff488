#pragma once
/// The overlap scheme's region beyond a capped cut. A hitting face that does not face
/// target side o counts for side s only where its depth behind s is at most its depth behind o plus
/// the face's reach behind o (contact_reach.hpp). Dropping the rest made the stored energy jump:
/// a face lying on the bisector of s and o (a brick turning through 45° with its edge pressed into
/// the corner of another) has the cut parallel to it, so the whole strip flipped in or out within
/// microns of motion, and the edge force of that cut (the jump over |∇φ| → 0) reached 0.32 MN in
/// one step of a collapsing wall and made 51.7 J. Beyond the cut the face now keeps the depth
/// d_B = (1 + κ)(d_o + reach) − κ·d_s (κ = kBeyondTaper), which equals d_s on the cut, so the
/// energy is continuous there and the cut carries no edge force; it fades to zero where d_s reaches
/// (1 + 1/κ)(d_o + reach), so a face that only dips behind o (a brick hanging over the edge of its
/// base) still gets nothing from the sliver of its side. The force beyond is the gradient of its
/// energy ½kn∫d_B² dA: −kn∫d_B·∇d_B, (1 + κ)·kn∫d_B along o's normal at the deepest corner (the
/// reach moves with it), the couple of the face's tilt to s, and the edge forces where the region
/// ends on a constraint fixed to the target.

#include <array>
#include <vector>

#include "block.hpp"
#include "contact.hpp"
#include "contact_overlap.hpp"
#include "contact_pair.hpp"
#include "contact_reach.hpp"
#include "face.hpp"

namespace cairn::dem {

/// integrals over a polygon projected on the plane (c, n) of a depth d(p) = depth(p) that is not
/// the depth behind that plane: area, d1, d2 as OverlapIntegrals, slope the gradient of the
/// polygon's own depth h behind the plane and tilt = ∫d²∇h dA, moment = ∫p·d dA and first = ∫p dA
/// over the polygon's own points p (on the hitting face), m⁴ and m³
OverlapIntegrals integrate_beyond(const ClipPolygon& poly, const Vec3& c, const Vec3& n, const Affine& depth);

/// What one sub-cell of a hitting face needs to apply its regions beyond the capped cuts of target
/// side s: the cell (unclipped; on a deformable hitting face its 4 triangles, each two neighbouring
/// corners and the cell's centre, with their natural coordinates on the face), the side's
/// constraints (the first `side_count` are the other sides' planes and cuts, `caps` marks the capped
/// cuts), then the target face's (up to `count`), the target face (plane c, n) and the hitting face.
struct BeyondCell {
    int parts = 1;                                   ///< 1: the cell (rigid hitting face); 4: its triangles
    const std::array<ClipPolygon, 4>* pieces = nullptr;
    std::array<std::array<Vec2, 3>, 4> piece_xi{};   ///< deformable: the triangles' corners on the hitting face
    const Affine* cons = nullptr;
    int side_count = 0, count = 0;
    const ReachCap* caps = nullptr;
    const PairGeometry* g = nullptr;
    Vec3 c = Vec3::Zero(), n = Vec3::UnitZ();
    const Quad* hit_face = nullptr;
    const Quad* target_face = nullptr;
    double kn = 0.0;   ///< N/m³
    double scale = 1.0;   ///< the weight of these constraints' rule (the facing rule's blend): every force times it
};

/// the energy stored beyond the capped cuts of one cell (J, not scaled); its forces, times
/// in.scale, are spread on the blocks, or
/// kept in `kept` when given (hit face f of hb on target face tf of tb). A deformable hitting face
/// takes each triangle's forces by their barycentric weights, without the tilt couple (as the
/// region before the cut); a deformable target takes the forces along o's normal by the weights of
/// o's plane (through its corners, as SideFrames) and the rest by those of the target face's plane
/// (contact_pair.hpp, plane_weights)
double apply_beyond(const BeyondCell& in, Block& hb, int f, Block& tb, int tf, std::vector<SubForce>* kept);

}  // namespace cairn::dem
