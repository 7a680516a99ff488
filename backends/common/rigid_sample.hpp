#pragma once
/// What every rigid-body engine reads back from its bodies the same way: the sample of the free
/// blocks and probes, and the check that no block has left the numbers.

#include <functional>
#include <string>
#include <vector>

#include "rigid_blocks.hpp"

namespace cairn {

/// the sample at time t (s): state(b) of each free block (through add_block_state, which adds its
/// kinetic and gravitational energy), each probe placed on its block by com(index) (world, m) and
/// orientation(index) (block frame → world); energies beyond those and contacts are the caller's
Sample rigid_sample(double t, const std::vector<RigidBlock>& blocks, const Scene& scene,
                    const std::function<BlockState(const RigidBlock&)>& state, const std::function<Vec3(int)>& com,
                    const std::function<Quat(int)>& orientation);

/// "block 'NAME' position is not finite at t = T s" for the first free block whose com(index)
/// (world, m) is NaN or infinite at time t (s); "" when every one is finite
std::string non_finite_block(const std::vector<RigidBlock>& blocks, double t, const std::function<Vec3(int)>& com);

}  // namespace cairn
