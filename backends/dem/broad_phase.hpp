#pragma once
/// Broad phase: pairs of overlapping axis-aligned boxes by sweep and prune along x.

#include <utility>
#include <vector>

#include "geometry/hexahedron.hpp"

namespace cairn::dem {

/// index pairs (i < j) of overlapping boxes into `pairs`, sorted; `order` is scratch space
/// (both keep their capacity between calls)
void overlapping_pairs(const std::vector<Aabb>& boxes, std::vector<int>& order,
                       std::vector<std::pair<int, int>>& pairs);

}  // namespace cairn::dem
