#pragma once
/// A scene's boxes re-described in frames whose z is up: the same geometry, each box's frame axes
/// renamed so that +z is a fixed box's side the reference block rests on (of the sides it lies
/// beyond, the one facing most against gravity: a slope's face at any angle) and a free box's axis
/// nearest the first fixed block's top (up, on a level base). The reference kinds read a
/// block's frame z as its height and a base's frame +z as its top; a Y-up scene whose boxes are
/// written unturned (height along frame y) is then judged as the same scene written Z-up. General
/// hexahedra are kept as written.

#include <array>
#include <vector>

#include "backend/backend.hpp"
#include "scene/scene.hpp"

namespace cairn::cases {

/// the rotation (a signed permutation of the axes, det +1) from the block's new frame to its
/// frame as written: its third column is the written axis nearest up (z kept on a tie within 1e-9)
Mat3 upright_turn(const BlockDef& b, const Vec3& up);

/// the scene with every box's frame turned as above (corners, size, orientation, mesh divisions,
/// and the block-frame points of its loads and probes); boxes already upright are copied unchanged,
/// to the bit
Scene upright_frames(const Scene& scene);

/// the samples of a run of `scene` with each free block's orientation in its upright frame
std::vector<Sample> upright_samples(const Scene& scene, const std::vector<Sample>& samples);

/// divisions along the block-frame axes of block `b` of `scene`, renamed as upright_frames renames them
std::array<int, 3> upright_divisions(const Scene& scene, int b, const std::array<int, 3>& divisions);

}  // namespace cairn::cases
