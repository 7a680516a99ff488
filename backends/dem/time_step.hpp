#pragma once
/// Critical time step of the central-difference scheme for the contact springs.

#include <vector>

#include "block.hpp"
#include "scene/scene.hpp"

namespace cairn::dem {

/// largest squared frequency (rad²/s²) of a free block resting with one whole side on a rigid
/// base: normal springs kn·a and shear springs ks·a at its hitting points, all six rigid modes
/// (the block's mass and rotational inertia: exact, or its mass scheme's)
double side_contact_omega2(const Block& b, int side, const ContactLaw& law);

/// critical step of the contact springs, s: 2/ω·(√(1+ζ²) − ζ) with ω² the largest over the pairs
/// that can touch of the sum of the two blocks' side_contact_omega2 (an upper bound on a pair's
/// frequency; a fixed partner adds none, a free block with no free partner counts alone). A pair
/// can touch when the blocks' bounding boxes, grown by `reach` (m, the broad-phase margin), overlap;
/// reach < 0: every pair of free blocks (the two largest values anywhere)
double contact_critical_step(const std::vector<Block>& blocks, const ContactLaw& law, double reach = -1.0);

/// critical step of the hex8 elements, s: min over deformable blocks of 2/ω·(√(1+ζ²) − ζ),
/// ω the largest element frequency and ζ = β·ω/2; 0 when there is no deformable block
double element_critical_step(const std::vector<Block>& blocks);

}  // namespace cairn::dem
