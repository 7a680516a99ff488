#pragma once
/// Newmark's sliding block (Newmark 1965, "Effects of earthquakes on dams and embankments"): a
/// rigid block on a rigid horizontal base with Coulomb friction, driven along the base by loads
/// (a ground motion's −m·a_g among them). SI units. A base inclined or gravity in another direction
/// is the same block in the base's frame: the caller gives the drive along the plane and into it,
/// gravity included, with g = 0 (compare/cases/newmark.cpp).

#include <functional>
#include <vector>

#include "geometry/types.hpp"

namespace cairn::oracle {

/// The block's motion relative to the base, sampled on the integration grid.
struct SlidingHistory {
    std::vector<double> t;    ///< s
    std::vector<Vec2> x;      ///< displacement along the base (world x, y), m
    double slide_time = 0.0;  ///< total time spent sliding, s
    int onsets = 0;           ///< times the block went from holding to sliding
    double peak_ratio = 0.0;  ///< largest |f_h|/n of the drive (the friction demand), dimensionless
    /// displacement at time `at` (s), linearly interpolated; the last value past the end
    Vec2 at(double at) const;
};

/// Integrates the rigid-plastic block over [0, duration] (s), from rest or launched along the base
/// at v0 (m/s, world x and y): `drive(t)` is the applied
/// force per unit mass (m/s², world; +z up), gravity g (m/s²) acts along −z, friction μ. The base
/// presses with n = g − f_z per unit mass (n ≤ 0: the block is free); the block holds while
/// |f_h| ≤ μ·n, and slides against its relative velocity with μ·n otherwise, stopping where the
/// velocity vanishes if friction can then hold it. Midpoint steps of h = max(1e-5 s, duration/2e6)
/// (at most 2e6 steps), with the stop found within its step: error O(h²) away from the stops,
/// O(h·v) at each.
SlidingHistory newmark_slide(const std::function<Vec3(double)>& drive, double g, double mu, double duration,
                              const Vec2& v0 = Vec2::Zero());

}  // namespace cairn::oracle
