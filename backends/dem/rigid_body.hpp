#pragma once
/// A rigid body integrated by central differences (kick-drift-kick leapfrog) with exact finite
/// rotations: the angular momentum is kicked by the torque, and the orientation drifts by the
/// implicit-midpoint rotation of a free body with that angular momentum.

#include "geometry/types.hpp"

namespace cairn::dem {

/// State and mass properties of one rigid block.
struct RigidBody {
    double mass = 0.0;                      ///< kg
    Mat3 inertia_body = Mat3::Identity();   ///< inertia about the centre of mass, body axes, kg·m²
    Mat3 inv_inertia_body = Mat3::Identity();///< its inverse, 1/(kg·m²)
    Vec3 x = Vec3::Zero();                  ///< centre of mass, world, m
    Quat q = Quat::Identity();              ///< orientation body → world
    Vec3 v = Vec3::Zero();                  ///< centre-of-mass velocity, m/s
    Vec3 L = Vec3::Zero();                  ///< angular momentum about the centre of mass, world, kg·m²/s

    /// angular velocity from the angular momentum at the current orientation, rad/s
    Vec3 omega() const;
    /// the same, with the orientation's rotation matrix r already at hand
    Vec3 omega(const Mat3& r) const { return r * (inv_inertia_body * (r.transpose() * L)); }
    /// set the angular momentum from an angular velocity (rad/s)
    void set_omega(const Vec3& w);
    /// kinetic energy, J
    double kinetic_energy() const;
    /// velocity of a world point attached to the body, m/s
    Vec3 point_velocity(const Vec3& world_point) const { return v + omega().cross(world_point - x); }
};

/// half of a central-difference velocity update: momenta += h·(force, torque), with
/// mass-proportional damping α (1/s) treated implicitly; returns the energy dissipated, J
double kick(RigidBody& b, const Vec3& force, const Vec3& torque, double h, double alpha);

/// kinetic energy of the velocity change a half kick of h (s) under (force N, torque N·m) gives
/// the body at its current orientation, ½·h²·(|F|²/m + τ·I⁻¹τ), J
double half_kick_energy(const RigidBody& b, const Vec3& force, const Vec3& torque, double h);

/// move the body over dt at its current momenta (translation and free rotation)
void drift(RigidBody& b, double dt);

/// the rotation vector θ·axis of a unit quaternion, rad
Vec3 rotation_vector(const Quat& q);

/// unit quaternion of a rotation vector, rad
Quat quat_from_rotation_vector(const Vec3& r);

}  // namespace cairn::dem
