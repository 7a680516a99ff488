#pragma once
/// An independent rocking oracle: Housner's nonlinear equation of a rigid rectangular block on a
/// rigid base under horizontal (and optionally vertical) ground acceleration, integrated by an
/// adaptive Dormand–Prince 5(4) scheme with dense output and located events (uplift, impact,
/// overturning); docs/validation.md, "The rocking oracle", derives the equation and the criteria.
///
/// θ is the rotation of the block about the bottom edge it rocks on: θ > 0 about the +x edge (the
/// centre moves towards +x), θ < 0 about the −x edge. With the ground acceleration a_g along +x and
/// a_v upwards, and s = sgn θ the edge in use:
///   θ̈ = −p² [ (1 + a_v/g) sin(α s − θ) + (a_g/g) cos(α s − θ) ],   p² = m g R / I_O = 3g / (4R).

#include <functional>
#include <string>
#include <vector>

#include "analytic/oracles.hpp"

namespace cairn::oracle {

/// A ground motion as the oracle sees it: accelerations of the base in the world.
struct BaseMotion {
    std::function<double(double)> horizontal;   ///< a_g(t) along +x, m/s²; empty = none
    std::function<double(double)> vertical;     ///< a_v(t) upwards, m/s²; empty = none
    double end = 0.0;                           ///< s: both are zero from here on
    std::vector<double> breaks;                 ///< s, ascending: kinks or jumps (steps end there)
};

/// How to run the oracle.
struct RockingOptions {
    double restitution = -1.0;     ///< impact angular-velocity ratio r; < 0 = Housner's 1 − 1.5 sin²α
    double theta0 = 0.0;           ///< initial rotation, rad (|θ0| < α)
    double omega0 = 0.0;           ///< initial angular velocity, rad/s (with θ0 ≠ 0)
    double duration = 10.0;        ///< s: integrate at most this long
    bool linear = false;           ///< the linearised equation (sin x → x, cos x → 1, tan α → α)
    bool settle = true;            ///< stop once the motion has ended and the block cannot overturn
    double rtol = 1e-10;           ///< relative tolerance of a step
    double atol = 1e-12;           ///< absolute tolerance of a step, rad and rad/s
    double max_step = 5e-3;        ///< s: largest step, and the scan step while the block rests
    std::vector<double> output_times;   ///< s, ascending: θ and θ̇ are reported there
};

/// What the block did.
struct RockingResult {
    bool overturned = false;      ///< |θ| reached π/2: the block lies on its side
    double overturn_time = -1.0;  ///< s, when |θ| reached π/2 (−1: never)
    double exceed_time = -1.0;    ///< s, when |θ| first passed α (−1: never)
    double max_abs_theta = 0.0;   ///< largest |θ| reached, rad
    int impacts = 0;              ///< impacts (θ through 0 while rocking)
    std::vector<double> uplift_times;   ///< s: each start of rocking from rest
    std::vector<double> impact_times;   ///< s
    std::vector<double> impact_omega;   ///< θ̇ just before each impact, rad/s
    std::vector<double> theta;    ///< rad at each output time (±π/2 once overturned)
    std::vector<double> omega;    ///< rad/s at each output time (0 once overturned)
    double end_time = 0.0;        ///< s, where the integration stopped
    std::string stop;             ///< "overturned", "settled" or "duration"
    long long steps = 0;          ///< accepted steps
};

/// Housner's block under a base motion.
class RockingOracle {
public:
    /// half-width b and half-height h of the block across the rocking axis (m), gravity g (m/s²)
    RockingOracle(double b, double h, double g);

    const HousnerBlock& block() const { return block_; }
    /// slenderness α, rad
    double alpha() const { return block_.alpha(); }
    /// frequency parameter p, 1/s
    double p() const { return block_.p(); }
    /// Housner's impact angular-velocity ratio 1 − 1.5 sin²α
    double housner_restitution() const { return block_.velocity_ratio(); }

    /// θ̈ (rad/s²) on edge s (±1) at θ, θ̇ under base accelerations a_g, a_v (m/s²)
    double acceleration(int s, double theta, double a_g, double a_v, bool linear) const;
    /// mechanical energy per unit I_O/(m g R)·p² (rad²/s²) of the free block: ½θ̇² + p²[cos(α−|θ|) − cos α]
    /// (linear: ½θ̇² + p²(α|θ| − θ²/2)); zero at rest, p²(1 − cos α) at the top of the hill |θ| = α
    double energy(double theta, double omega, bool linear = false) const;
    /// the base acceleration a_g (m/s²) past which a resting block uplifts: (g + a_v)·tan α (linear: α)
    double uplift_threshold(double a_v, bool linear = false) const;

    /// integrate the block from (θ0, θ̇0), or from rest, under the motion
    RockingResult run(const BaseMotion& motion, const RockingOptions& options) const;

private:
    HousnerBlock block_;
};

}  // namespace cairn::oracle
