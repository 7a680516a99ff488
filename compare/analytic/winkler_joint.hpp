#pragma once
/// A rectangular bed joint of no-tension Winkler springs under a normal force and a small lean in
/// any direction: where its normal resultant acts (BlockStack's pushes at an angle to the joint).

#include <Eigen/Dense>

namespace cairn::oracle {

/// The first moment ∫ kn·d⁺·r dA (N·m, r from the joint's centre in its axes) of a rectangular
/// joint of half-sizes `a` along x and `c` along y (m) with springs kn (N/m³) carrying the normal
/// force `n` (N, > 0), when the part above leans by the small rotation vector `lean` (rad): its
/// closure is d = w + lean·r, w set so that ∫ kn·d⁺ dA = n. It is n times the offset of the
/// normal resultant from the centre; kn·I·lean while the whole joint stays closed.
Eigen::Vector2d winkler_joint_moment(const Eigen::Vector2d& lean, double n, double a, double c, double kn);

}  // namespace cairn::oracle
