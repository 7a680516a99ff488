#pragma once
/// Broad phase: pairs of overlapping axis-aligned boxes by sweep and prune along x.

#include <utility>
#include <vector>

#include "geometry/hexahedron.hpp"

namespace cairn::dem {

/// index pairs (i < j) of overlapping boxes, in a deterministic order
std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Aabb>& boxes);

}  // namespace cairn::dem
