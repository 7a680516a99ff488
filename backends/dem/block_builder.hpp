#pragma once
/// Building engine blocks from scene blocks, and locating material points in them.

#include "block.hpp"
#include "scene/scene.hpp"

namespace cairn::dem {

/// a block of the engine from its definition: rigid (one element, pose and momenta) or
/// deformable (its mesh, mass scheme and β from the scene); fixed blocks are always rigid
Block make_block(const BlockDef& def, const Scene& scene);

/// a material point of a block: the element holding it and its natural coordinates there
struct MaterialPoint {
    int block = 0;
    Vec3 frame = Vec3::Zero();   ///< block frame, m
    int element = 0;             ///< index of the element holding it
    Vec3 xi = Vec3::Zero();      ///< natural coordinates in that element
};

/// locate a block-frame point in a block's mesh (nearest element when outside)
MaterialPoint locate(const Block& b, int block_index, const Vec3& frame_point);

/// world position of a material point, m
Vec3 world_position(const Block& b, const MaterialPoint& p);

/// add a force (N) at a material point to the block's node forces
void add_point_force(Block& b, const MaterialPoint& p, const Vec3& force);

}  // namespace cairn::dem
