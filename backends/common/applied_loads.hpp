#pragma once
/// The loads on the rigid blocks at one time, for the reference engines: the scene's given loads
/// and the ground motion's body loads (one per free block and component) through one function, so
/// that every engine applies the same forces and books the same work.

#include <functional>
#include <vector>

#include "scene/scene.hpp"

namespace cairn {

/// One load acting now.
struct AppliedLoad {
    int block = 0;               ///< index into Scene::blocks (a free block)
    Vec3 force = Vec3::Zero();   ///< N, world
    Vec3 point = Vec3::Zero();   ///< material point of application, block frame, m
};

/// the loads acting at time t (s) on free blocks, with their forces (a zero factor is left out);
/// `out` is cleared and refilled, so its storage is reused from step to step
void applied_loads(const Scene& scene, double t, std::vector<AppliedLoad>& out);

/// their power Σ F·v, W, given the world velocity (m/s) of a block's material point
double load_power(const std::vector<AppliedLoad>& loads,
                  const std::function<Vec3(int block, const Vec3& point)>& point_velocity);

}  // namespace cairn
