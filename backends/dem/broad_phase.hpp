#pragma once
/// Broad phase: the pairs of overlapping axis-aligned boxes. Few boxes: sweep and prune along x.
/// Many: a hashed uniform grid whose cell is the median box size, so the work per refresh grows
/// with the number of boxes, not with its square (or power 1.5 for a wall swept along one axis);
/// boxes much larger than a cell (a base, the ground) are tested against every box.

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/hexahedron.hpp"

namespace cairn::dem {

/// The broad phase with its scratch space, kept between calls so that a steady state allocates
/// nothing.
class BroadPhase {
public:
    /// index pairs (i < j) of overlapping boxes into `pairs`, sorted
    void overlapping_pairs(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs);
    /// the grid's cell edge at the last call (0: swept along x), m
    double cell() const { return cell_; }

private:
    void sweep(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs);
    bool grid(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs);

    double cell_ = 0.0;
    std::vector<int> order_;                       // sweep: boxes by lower x
    std::vector<double> extent_;                   // per box: largest edge, m
    std::vector<double> median_;                   // a copy of extent_ for the median
    std::vector<int> large_;                       // boxes tested against all
    std::vector<std::array<int32_t, 6>> range_;    // per box: its cells, lo and hi per axis
    std::vector<std::pair<uint64_t, int>> entry_;  // (cell key, box) for every cell of every box
    std::vector<std::pair<uint64_t, int>> sorted_; // the entries by hash bucket
    std::vector<int> start_;                       // first entry of each bucket
};

/// index pairs (i < j) of overlapping boxes into `pairs`, sorted, by sweep and prune along x;
/// `order` is scratch space (both keep their capacity between calls)
void overlapping_pairs(const std::vector<Aabb>& boxes, std::vector<int>& order,
                       std::vector<std::pair<int, int>>& pairs);

}  // namespace cairn::dem
