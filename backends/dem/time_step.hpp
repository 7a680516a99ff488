#pragma once
/// Critical time step of the central-difference scheme for the contact springs.

#include <vector>

#include "block.hpp"
#include "scene/scene.hpp"

namespace cairn::dem {

/// largest squared frequency (rad²/s²) of a free block resting with one whole face on a rigid
/// base: normal springs kn·a and shear springs ks·a at its hitting points, all six rigid modes
double face_contact_omega2(const Block& b, int face, const ContactLaw& law);

/// critical step, s: 2/ω·(√(1+ζ²) − ζ) with ω² the sum of the two largest block values of
/// face_contact_omega2 (one block: its own) — an upper bound on the pair's frequency
double critical_step(const std::vector<Block>& blocks, const ContactLaw& law);

}  // namespace cairn::dem
