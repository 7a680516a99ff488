#pragma once
/// The stiffest vibration of a rigid body on a bed of penalty springs: what limits the time step
/// of an engine that integrates those springs (dem's contact, MuJoCo's matched contact).

#include <utility>
#include <vector>

#include "geometry/types.hpp"

namespace cairn {

/// one spring of the bed: its point (m, world) and tributary area (m²)
using BedSpring = std::pair<Vec3, double>;

/// the largest squared angular frequency (rad²/s²) of a rigid body of mass m (kg) and world
/// inertia I (kg·m², about its centre of mass c) held by springs kn·a along the bed's unit normal
/// n and ks·a along both tangents (kn, ks per unit area, N/m³): the largest eigenvalue of
/// M^(−1/2)·K·M^(−1/2) over the body's six rigid motions
double spring_bed_omega2(const std::vector<BedSpring>& springs, const Vec3& n, double kn, double ks, const Vec3& c,
                         double m, const Mat3& inertia);

}  // namespace cairn
