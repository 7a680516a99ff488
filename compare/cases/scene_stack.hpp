#pragma once
/// The scene's free blocks as a stack of layers for the stack oracle (compare/analytic,
/// BlockStack): the pushover reference's, and the compare report's estimate of what dem's
/// compliant joints take off a rigid stack's overturning multiplier.

#include <optional>
#include <string>

#include "analytic/stack_pushover.hpp"
#include "scene/scene.hpp"

namespace cairn::cases {

/// the stack of the scene's free blocks: blocks grouped into layers by their bottom height, each
/// layer's width along the ground motion's direction and depth across it
oracle::BlockStack scene_stack(const Scene& scene);
/// the same, only where the free blocks form a centred stack under the scene's one horizontal
/// record: full layers (no gaps) of blocks square to each other, each resting on the one below,
/// centred on the first's vertical axis (1 % of its width), a layer of several blocks only where
/// each spans it along the push (a wall pushed out of its plane), the first layer on a fixed block
/// that runs past it along the push (past both its sides for a push at an angle to the layers'
/// axes). Its layers' width is along the first free block's first horizontal axis, and push_angle
/// the push's angle to it. Otherwise nothing, and `why` (when given) says what is not a centred
/// stack, naming the key.
std::optional<oracle::BlockStack> centred_stack(const Scene& scene, std::string* why = nullptr);

}  // namespace cairn::cases
