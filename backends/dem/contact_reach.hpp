#pragma once
/// The overlap scheme's constraints of a target side, and the refresh's test of which hitting
/// faces can reach a target block before the next refresh (the others are never candidates).

#include <array>
#include <vector>

#include "block.hpp"
#include "contact_overlap.hpp"
#include "contact_pair.hpp"

namespace cairn::dem {

/// overlap scheme: the contacts are refreshed before any block turns more than this (rad), so
/// that a side square to another (within 1e-3 rad: never a hitting side) is left out at refresh
constexpr double kRefreshTurn = 2e-4;

/// the rate at which the region beyond a capped cut fades (contact_overlap_beyond.hpp): its depth
/// is (1 + κ)(d_o + reach) − κ·d_s, zero where d_s = (1 + 1/κ)(d_o + reach)
constexpr double kBeyondTaper = 0.25;

/// most constraints of one target side: depth, 4 face edges, and per other side flush and entering
constexpr int kMaxSideConstraints = 16;

/// overlap scheme, the facing rule: a hitting side faces another side o of the target when the
/// product of their outward normals c = n_h·n_o is below −kFacingBegin (it hits o too, and s keeps
/// no point nearer to o); fully from −kFacingEnd, and blended over the band between, so that the
/// energy does not jump as a side square to o turns past it (docs/dem.md, overlap scheme)
constexpr double kFacingBegin = 1e-3;
constexpr double kFacingEnd = 2e-2;

/// the weight of the rule for a side not faced at c = n_h·n_o (the rest, 1 − w, is the faced rule):
/// 1 from −kFacingBegin up, 0 from −kFacingEnd down, a smoothstep between (its slope, and with it
/// the blend's couple, goes to zero at both ends) (dimensionless)
inline double not_facing_weight(double c) {
    if (!(c < -kFacingBegin)) return 1.0;
    if (!(c > -kFacingEnd)) return 0.0;
    const double t = (c + kFacingEnd) / (kFacingEnd - kFacingBegin);
    return t * t * (3.0 - 2.0 * t);
}

/// dw/dc of not_facing_weight at c (dimensionless): zero outside the band and at its ends
inline double not_facing_slope(double c) {
    if (!(c < -kFacingBegin) || !(c > -kFacingEnd)) return 0.0;
    const double t = (c + kFacingEnd) / (kFacingEnd - kFacingBegin);
    return 6.0 * t * (1.0 - t) / (kFacingEnd - kFacingBegin);
}

/// The affine constraints of target side s that do not depend on the target face (docs/dem.md,
/// overlap scheme): behind every other side plane (flush within flush_tol) and not entering
/// through another side. `hit_normal` is the hitting side's outward unit normal; `loose` gives
/// every entering constraint the closer tolerance whatever the hitting normal (the refresh's bound
/// over any orientation the blocks reach), widened to cover the region beyond a capped cut where
/// `hit_face` may be capped while its points move up to `motion` (m) relative to the target.
/// Otherwise, with `hit_face`, the closer tolerance of a side o the hitting side does not face is
/// at most how far the face's corners reach behind o's plane. `facing`, where given, says per side
/// o whether the hitting side faces it (1) or not (0); elsewhere (−1) c < −kFacingBegin decides.
/// Returns the count written to `out`.
/// A closer constraint whose tolerance is the hitting face's reach behind side o: its offset moves
/// with the face's corner `corner` (index into the face's quad) along o's outward normal.
struct ReachCap {
    int corner = -1;   ///< -1: the constraint does not move with the hitting face
    int side = -1;     ///< o: the target side whose plane the reach is measured from
};

int side_constraints(const PairGeometry& g, int s, const Vec3& hit_normal, bool loose,
                     std::array<Affine, kMaxSideConstraints>& out, const Quad* hit_face = nullptr,
                     std::array<ReachCap, kMaxSideConstraints>* caps = nullptr, double motion = 0.0,
                     const std::array<signed char, 6>* facing = nullptr);

/// true when hitting face f of block h may act on block t at some step before the next refresh,
/// while no point of either block moves more than half of `margin` (m) nor turns more than
/// kRefreshTurn: some target side faces the face's side within that turn, may be its target, and no constraint of
/// that side (with the whole side's depth and edges when the side is one face) misses all four
/// corners of the face by more than the constraint can change over the motion. `frames` are every
/// block's side frames now; `g` is scratch for the pair. Whatever this rejects never carries force
/// in the interval, so pruning it leaves every result unchanged.
bool may_act(const std::vector<Block>& blocks, const std::vector<SideFrames>& frames, int h, int f, int t,
             double margin, PairGeometry& g);

}  // namespace cairn::dem
