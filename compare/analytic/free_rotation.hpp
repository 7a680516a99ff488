#pragma once
/// A torque-free rigid body: Euler's equations I ω̇ + ω × Iω = 0 in body axes and the orientation,
/// integrated by classical RK4 with a small fixed step, as an independent reference for the
/// engines' rotation (no closed form for a general inertia).

#include <vector>

#include "geometry/types.hpp"

namespace cairn::oracle {

/// a free rigid body of body-axes inertia I (kg·m², symmetric positive definite)
struct FreeRotation {
    Mat3 inertia;              ///< body axes, kg·m²
    double step = 1e-5;        ///< RK4 step, s

    /// orientation (body → world) and body angular velocity (rad/s)
    struct State {
        Quat q = Quat::Identity();
        Vec3 omega_body = Vec3::Zero();
        /// world angular velocity, rad/s
        Vec3 omega_world() const { return q * omega_body; }
    };
    /// the states at each time (ascending, ≥ 0) from `start` at t = 0
    std::vector<State> states(const State& start, const std::vector<double>& times) const;
    /// kinetic energy ½ ωᵀIω, J
    double energy(const State& s) const;
    /// angular momentum in the world frame, kg·m²/s
    Vec3 momentum(const State& s) const;
};

}  // namespace cairn::oracle
