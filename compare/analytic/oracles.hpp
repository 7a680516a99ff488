#pragma once
/// Analytic references of the validation cases (docs/validation.md), SI units.

#include <vector>

namespace cairn::oracle {

/// a block of mass m (kg) resting on a penalty spring K = kn·A (N/m) under gravity g (m/s²)
struct RestingBlock {
    double mass, stiffness, g;
    /// equilibrium penetration mg/K, m
    double penetration() const { return mass * g / stiffness; }
    /// angular frequency √(K/m), rad/s
    double omega() const;
    /// period 2π/ω, s
    double period() const;
};

/// the same block dropped from a gap h (m) onto the spring, no damping
struct DroppedBlock {
    double mass, stiffness, g, gap;
    /// speed at first contact √(2gh), m/s
    double impact_speed() const;
    /// time of first contact √(2h/g), s
    double first_contact() const;
    /// contact duration [π + 2 atan(g/(ω v0))]/ω, s
    double contact_time() const;
    /// largest penetration [mg + √((mg)² + 2Kmgh)]/K, m
    double max_penetration() const;
    /// bounce period 2 v0/g + contact time, s
    double bounce_period() const;
};

/// dashpot of damping ratio ζ on a spring K (N/m) and a mass m (kg): 2ζ√(K m), N·s/m
double dashpot_for_ratio(double zeta, double stiffness, double mass);

/// The block of DroppedBlock on a spring K with a dashpot c whose force max(0, −K x − c ẋ) never
/// pulls: the contact releases when spring + dashpot reach zero (the "gravity + release" rule of
/// the validation). No closed form: the contact phase is integrated with RK4 at T/2e5 steps.
struct DampedDrop {
    double mass, stiffness, damping, g, gap;   ///< kg, N/m, N·s/m, m/s², m

    /// what one contact phase does to a block arriving at v0 = √(2 g gap)
    struct Bounce {
        double contact_time = 0.0;      ///< from touching to leaving the contact plane, s
        double max_penetration = 0.0;   ///< m
        double exit_speed = 0.0;        ///< upward speed when the bottom leaves the plane, m/s
        double restitution = 0.0;       ///< exit_speed / v0
    };
    /// the first contact phase
    Bounce first_bounce() const;
    /// time from the first touch to the second touch: contact time + 2 e v0 / g, s
    double bounce_period() const;
    /// height of the bottom above the contact plane at each time (ascending, from release at
    /// rest at t = 0), negative inside the contact, m
    std::vector<double> heights(const std::vector<double>& times) const;
};

/// acceleration of a block pulled by H (N) on a flat base with friction μ; 0 if it holds, m/s²
double pulled_block_acceleration(double mass, double g, double pull, double mu);

/// acceleration down a plane inclined θ (rad) with friction μ; 0 if it holds, m/s²
double incline_acceleration(double g, double theta, double mu);
/// displacement down a plane inclined θ (rad), friction μ, at time t (s) of a block launched along
/// its fall line at v0 (m/s, + downhill): braked at g(sin θ + μ cos θ) uphill, at g(μ cos θ − sin θ)
/// downhill when tan θ < μ (then it stops and holds), sped up at g(sin θ − μ cos θ) otherwise, m
double launched_on_incline(double g, double theta, double mu, double v0, double t);

/// Housner's rigid rectangular block of half-width b and half-height h (m) rocking on a rigid base
struct HousnerBlock {
    double b, h, g;
    /// slenderness α = atan(b/h), rad
    double alpha() const;
    /// R = √(b²+h²), m
    double radius() const;
    /// frequency parameter p = √(3g/(4R)), 1/s
    double p() const;
    /// exact time from release at rest at θ0 (rad, 0 < θ0 < α) to the first impact, s
    double first_impact(double theta0) const;
    /// linearised time to the first impact, s
    double first_impact_linear(double theta0) const;
    /// angular velocity at the first impact, rad/s
    double impact_omega(double theta0) const;
    /// angular-velocity ratio of an impact, 1 − (3/2) sin²α
    double velocity_ratio() const;
    /// amplitude after n impacts (rad) from release at θ0
    double amplitude_after(double theta0, int n) const;
    /// amplitude after n impacts with an impact angular-velocity ratio r (rad)
    double amplitude_after(double theta0, int n, double r) const;
    /// θ(t) (rad) at each time (ascending) from release at rest at θ0, integrating
    /// θ̈ = −p² sin(α sgnθ − θ) and scaling θ̇ by r at every impact (θ = 0)
    std::vector<double> angles(double theta0, double r, const std::vector<double>& times) const;
};

}  // namespace cairn::oracle
