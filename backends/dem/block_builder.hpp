#pragma once
/// Building engine blocks from scene blocks, and locating material points in them.

#include "block.hpp"
#include "run/run_limits.hpp"
#include "scene/scene.hpp"

namespace cairn::dem {

/// The memory a scene's model will take, estimated before anything is allocated.
struct BuildEstimate {
    double mesh_bytes = 0.0;       ///< nodes, elements, mass matrices of every block, bytes
    double hit_bytes = 0.0;        ///< hitting points and their contact state, bytes
    double nodes = 0.0;            ///< mesh nodes of every block
    double elements = 0.0;         ///< hex8 elements of every block
    double hit_points = 0.0;       ///< hitting points of every face (and the sides' critical-step grids)
    double largest_grid = 0.0;     ///< most points of one hitting grid (a face, or a side for the critical step)
    int largest_mesh = -1;         ///< index of the block whose mesh takes the most
    double bytes() const { return mesh_bytes + hit_bytes; }
};

/// the estimate for `scene` (counts in double: nothing overflows, whatever the divisions or spacing)
BuildEstimate estimate_build(const Scene& scene);

/// most hitting points of a scene without RunLimits::allow_large
constexpr double kMaxHitPoints = 1e6;

/// throw cairn::Error naming the file, the key and its value (the largest block's
/// mesh.divisions, or contact.grid_spacing) when the estimate exceeds the memory budget of
/// `limits`, when the hitting points pass kMaxHitPoints (unless allow_large), or when a count
/// would overflow the engine's 32-bit indices; called before the model is built
void check_build_size(const Scene& scene, const RunLimits& limits);

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
