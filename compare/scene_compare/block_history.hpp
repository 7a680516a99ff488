#pragma once
/// The histories of each free block in one run, as `cairn compare` plots and diffs them: centre
/// of mass position, rotation angle from the initial orientation, and speed.

#include <string>
#include <vector>

#include "backend/backend.hpp"

namespace cairn::scene_compare {

/// One free block's history in one run.
struct BlockHistory {
    std::vector<double> t;       ///< s
    std::vector<double> x, y, z; ///< centre of mass, m (world)
    std::vector<double> angle;   ///< angle of the rotation from the orientation at t = 0, rad (0 to π)
    std::vector<double> speed;   ///< centre-of-mass speed, m/s
};

/// the history of free block `f` (index among the free blocks, as in Sample::blocks)
BlockHistory block_history(const std::vector<Sample>& samples, int f);

/// The free blocks of a scene: scene index, display name and size.
struct FreeBlock {
    int scene_index = 0;     ///< index in Scene::blocks
    std::string name;        ///< the block's name, or "block N" (N = scene index + 1)
    double size = 0.0;       ///< smallest edge of its bounding box, m
};

/// the free blocks of `scene`, in Sample::blocks order
std::vector<FreeBlock> free_blocks(const Scene& scene);

}  // namespace cairn::scene_compare
