#pragma once
/// The minimum thickness of a semicircular arch of N equal voussoirs with radial joints under its
/// own weight (limit analysis, Heyman's assumptions: no tension, no sliding, infinite compressive
/// strength). A symmetric thrust line (crown thrust H at height y_c) must cross every joint within
/// its thickness; where it crosses joint k is linear in (H, H·y_c), so for a given thickness the
/// question is a two-variable linear feasibility problem, solved exactly by enumerating the
/// vertices of its polygon, and the minimum thickness follows by bisection.

namespace cairn::oracle {

/// a semicircular arch of centreline radius 1 and thickness t (in units of the radius)
struct SemicircularArch {
    int voussoirs;     ///< N ≥ 1: joints at k·π/N from the springing, k = 0 … N

    /// whether a thrust line fits inside every joint at thickness t/R
    bool thrust_line_fits(double t_over_r) const;
    /// the least t/R for which a thrust line fits (bisection to 1e-10)
    double minimum_thickness() const;
};

/// Milankovitch's minimum t/R of a semicircular arch with joints everywhere (the limit N → ∞)
constexpr double kMilankovitchMinimum = 0.1075;

}  // namespace cairn::oracle
