#pragma once
/// The horizontal ground acceleration, as a fraction λ of g, that turns a semicircular arch of N
/// equal voussoirs with radial joints into a mechanism (limit analysis, Heyman's assumptions: no
/// tension, no sliding, infinite compressive strength). The arch stands while a thrust line fits:
/// the force across joint k is the left springing's reaction (X, Z, and its moment M about the
/// centre) plus the weights and the horizontal loads λ·W of the voussoirs left of the joint, and
/// its line of action must cross every joint, springings included, within the thickness. For a
/// given λ that is a three-variable linear feasibility problem, solved exactly by enumerating the
/// vertices of its polyhedron; λ follows by bisection.

namespace cairn::oracle {

/// a semicircular arch of centreline radius 1 and thickness t (in units of the radius) under
/// gravity and a uniform horizontal acceleration λ·g
struct ArchUnderLateralLoad {
    int voussoirs;     ///< N ≥ 1: joints at k·π/N from the springing, k = 0 … N
    double thickness;  ///< t/R

    /// whether a thrust line fits inside every joint under λ (a fraction of g, ≥ 0)
    bool thrust_line_fits(double lambda) const;
    /// the largest λ at which a thrust line fits (bisection to 1e-6); 0 below the least thickness
    double collapse_acceleration() const;
};

}  // namespace cairn::oracle
