#pragma once
/// A planar rigid block rocking on rows of point springs: the reference for rocking on a penalty
/// contact. Each row of hitting points across the rocking axis is one point of area a with a normal
/// spring kn·a (never pulling, with an optional dashpot) and an elastic-then-Coulomb shear spring
/// ks·a from a stick anchor, capped at μ·Fn. The block is integrated here by velocity Verlet at a
/// step far below the springs' period, independently of any engine. SI units.

#include <vector>

namespace cairn::oracle {

/// one row of hitting points across the rocking axis
struct SpringRow {
    double x;      ///< position along the width from the base centre, m
    double area;   ///< tributary area of the whole row, m²
};

/// the rows of a rectangular base of `width` (across the axis) and `depth` (along it), split into
/// `divisions` equal faces across the width, each carrying a grid of hitting points at most
/// `spacing` apart (ceil(len/spacing) + 1 points, trapezoid weights); a point shared by two faces
/// is one row with both faces' areas
std::vector<SpringRow> spring_rows(double width, double depth, int divisions, double spacing);

/// the rocking history of a spring block
struct RockingTrace {
    std::vector<double> t, theta;     ///< sampled rotation (rad) about the axis, s
    std::vector<double> impacts;      ///< times θ crosses 0, s
    std::vector<double> amplitudes;   ///< largest |θ| between successive crossings (after each impact), rad
    double energy_error = 0.0;        ///< largest |E(t) + dissipated − E0| over the run, J
    double step = 0.0;                ///< integration step, s
};

/// a rigid block of width w, height h on rows of springs on a fixed flat base (top at z = 0)
struct SpringBlock {
    double width, height;   ///< across the rocking axis and vertical, m
    double mass;            ///< kg
    double g;               ///< m/s²
    double kn, ks, mu;      ///< N/m³, N/m³, dimensionless
    std::vector<SpringRow> rows;
    /// damping ratio ζ of the contact springs; each point gets c = 2ζ·a·√(k·m/A) (A the whole base),
    /// normal and (while it sticks) shear, the shear dashpot trimmed to keep |F| ≤ μ·Fn
    double zeta = 0.0;
    /// steps per period 2π/ω_max of the stiffest spring mode (bounded above by all springs on the
    /// corner's lever); 1000 keeps the amplitudes converged to 1e-4
    double steps_per_period = 1000.0;

    /// release at rest tilted θ0 (rad, 0 < θ0 < α) on its +x bottom edge, just touching; run for
    /// `duration` (s), sampling every `sample_dt` (s); throws cairn::Error beyond 1e8 steps
    RockingTrace rock(double theta0, double duration, double sample_dt) const;
    /// θ(t) at the given ascending times (rad), from the same run
    std::vector<double> angles(double theta0, const std::vector<double>& times) const;
};

/// θ of a trace at the given ascending times, linear between its samples (rad); the last value past its end
std::vector<double> angles_at(const RockingTrace& trace, const std::vector<double>& times);

}  // namespace cairn::oracle
