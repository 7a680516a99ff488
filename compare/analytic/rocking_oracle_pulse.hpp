#pragma once
/// Base motions for the rocking oracle: the one-sine, one-cosine and Ricker pulses, a sampled record,
/// and the closed form of the linearised block under a one-sine pulse (docs/validation.md, "The
/// rocking oracle").

#include <string>
#include <vector>

#include "analytic/rocking_oracle.hpp"
#include "scene/scene.hpp"

namespace cairn::oracle {

/// the shape of a pulse of ground acceleration
enum class PulseShape { sine, cosine, ricker };

/// "sine", "cosine", "ricker"; throws cairn::Error naming the value otherwise
PulseShape parse_pulse_shape(const std::string& name);
const char* to_string(PulseShape shape);

/// A pulse of horizontal ground acceleration starting at t = 0.
///   sine:   a_p sin(ω_p t) for 0 ≤ t ≤ 2π/ω_p (one full cycle)
///   cosine: a_p cos(ω_p t) for 0 ≤ t ≤ 2π/ω_p (jumps to a_p at t = 0)
///   ricker: a_p (1 − ω_p² τ²/2) exp(−ω_p² τ²/4), τ = t − 8/ω_p, for 0 ≤ t ≤ 16/ω_p
///           (ω_p is the frequency of the largest Fourier amplitude)
struct Pulse {
    PulseShape shape = PulseShape::sine;
    double amplitude = 0.0;   ///< a_p, m/s²
    double omega = 1.0;       ///< ω_p, rad/s
    /// length of the pulse, s
    double duration() const;
    /// a_g(t), m/s² (zero outside the pulse)
    double at(double t) const;
    /// the pulse as the oracle's base motion
    BaseMotion motion() const;
    /// the pulse sampled every dt (s) from 0 to its end, for a scene's ground motion (m/s²)
    TimeSeries sampled(double dt) const;
};

/// a sampled record (m/s² along +x) times `scale` as the oracle's base motion; its samples are breaks
BaseMotion record_motion(const TimeSeries& record, double scale = 1.0);

/// The linearised block (sin x → x, cos x → 1) under the one-sine pulse a_p sin(ω_p t) from rest:
/// it uplifts about its −x edge at t_u = asin(g α / a_p)/ω_p and then, until its first impact,
///   θ(t) = −α + C sin(ω_p t) + A cosh p(t − t_u) + B sinh p(t − t_u),   C = (a_p/g) p²/(p² + ω_p²),
///   A = α − C sin(ω_p t_u),  B = −C (ω_p/p) cos(ω_p t_u);
/// past the pulse's end T = 2π/ω_p the free solution −α + A' cosh p(t − T) + B' sinh p(t − T)
/// continues θ(T), θ̇(T). Needs a_p > g α.
struct LinearSinePulse {
    double p, alpha, g;       ///< 1/s, rad, m/s²
    double amplitude, omega;  ///< a_p (m/s²), ω_p (rad/s)
    /// uplift time t_u, s
    double uplift_time() const;
    /// θ (rad) and θ̇ (rad/s) at t ≥ t_u, valid until the first impact
    std::array<double, 2> state(double t) const;
};

}  // namespace cairn::oracle
