#pragma once
/// A bilinear quadrilateral face given by 4 corner points (counter-clockwise seen from outside):
/// evaluation in natural coordinates (ξ, η) ∈ [-1, 1]², projection of a point, hitting-point grids.

#include <array>
#include <vector>

#include "geometry/types.hpp"

namespace cairn::dem {

using Quad = std::array<Vec3, 4>;

/// bilinear weights of the 4 corners at (ξ, η)
std::array<double, 4> quad_weights(const Vec2& xi);

/// the point of the face at (ξ, η)
Vec3 quad_point(const Quad& c, const Vec2& xi);

/// outward unit normal at (ξ, η)
Vec3 quad_normal(const Quad& c, const Vec2& xi);

/// closest point of the face's bilinear surface to p (natural coordinates not clamped)
struct Projection {
    Vec2 xi = Vec2::Zero();     ///< natural coordinates of the foot point
    Vec3 point = Vec3::Zero();  ///< the foot point, m
    Vec3 normal = Vec3::UnitZ();///< outward unit normal there
};
Projection project(const Quad& c, const Vec3& p, Vec2 start = Vec2::Zero());

/// a hitting point of a face: natural coordinates and tributary area
struct HitPoint {
    Vec2 xi = Vec2::Zero();   ///< natural coordinates on the hitting face
    double area = 0.0;        ///< tributary area, m² (the face's points sum to its area)
};

/// the face corners plus a regular grid of virtual points no farther apart than `spacing` (m);
/// tributary areas by the trapezoid rule
std::vector<HitPoint> hit_grid(const Quad& c, double spacing);

/// area of the face, m²
double quad_area(const Quad& c);

}  // namespace cairn::dem
