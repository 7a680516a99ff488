#pragma once
/// Eigen aliases used across cairn.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cairn {
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;
}  // namespace cairn
