#pragma once
/// Geometry of a convex hexahedron given by its 8 corners (hex8 order):
/// corners 0-3 on the bottom face (ζ = -1) counter-clockwise seen from above, 4-7 above them.
/// Natural coordinates of corner i: ξ = ±1, η = ±1, ζ = ±1 as in kCornerSigns.

#include <array>
#include <string>

#include "geometry/types.hpp"

namespace cairn {

using Corners = std::array<Vec3, 8>;

/// natural coordinates (ξ, η, ζ) of the 8 corners
extern const std::array<std::array<int, 3>, 8> kCornerSigns;

/// corner indices of the 6 faces, ordered so that (c1-c0)×(c3-c0) points outward:
/// 0: ζ=-1 (bottom), 1: ζ=+1 (top), 2: η=-1, 3: ξ=+1, 4: η=+1, 5: ξ=-1
extern const std::array<std::array<int, 4>, 6> kFaceCorners;

/// corners of a box of edge lengths `size` (m) centred on the origin
Corners box_corners(const Vec3& size);

/// the shortest of the 12 edges, m
double shortest_edge(const Corners& c);

/// point of the trilinear hexahedron at natural coordinates (ξ, η, ζ) ∈ [-1, 1]³
Vec3 trilinear_point(const Corners& c, const Vec3& natural);

/// mass, centre of mass and inertia tensor of a homogeneous hexahedron (exact for trilinear geometry)
struct MassProperties {
    double volume = 0.0;            ///< m³
    double mass = 0.0;              ///< kg
    Vec3 centre = Vec3::Zero();     ///< centre of mass in the corners' frame, m
    Mat3 inertia = Mat3::Zero();    ///< inertia tensor about the centre, corners' axes, kg·m²
};
MassProperties mass_properties(const Corners& c, double density);

/// empty if the corners form a convex hexahedron with planar-enough faces and positive volume,
/// otherwise the reason
std::string convexity_problem(const Corners& c);

/// axis-aligned bounds of a point set
struct Aabb {
    Vec3 lo = Vec3::Constant(1e300);
    Vec3 hi = Vec3::Constant(-1e300);
    void add(const Vec3& p) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
    void inflate(double m) { lo.array() -= m; hi.array() += m; }
    bool overlaps(const Aabb& o) const {
        return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
    }
};

}  // namespace cairn
