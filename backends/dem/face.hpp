#pragma once
/// A bilinear quadrilateral face given by 4 corner points (counter-clockwise seen from outside):
/// evaluation in natural coordinates (ξ, η) ∈ [-1, 1]², projection of a point, hitting-point grids.

#include <array>
#include <vector>

#include "geometry/types.hpp"

namespace cairn::dem {

using Quad = std::array<Vec3, 4>;

/// bilinear weights of the 4 corners at (ξ, η)
inline std::array<double, 4> quad_weights(const Vec2& xi) {
    const double a = 1 - xi[0], b = 1 + xi[0], c = 1 - xi[1], d = 1 + xi[1];
    return {0.25 * a * c, 0.25 * b * c, 0.25 * b * d, 0.25 * a * d};
}

/// the point of the face at (ξ, η)
inline Vec3 quad_point(const Quad& c, const Vec2& xi) {
    auto w = quad_weights(xi);
    return w[0] * c[0] + w[1] * c[1] + w[2] * c[2] + w[3] * c[3];
}

/// outward unit normal at (ξ, η)
Vec3 quad_normal(const Quad& c, const Vec2& xi);
/// outward unit normal at the centre (ξ = η = 0): quad_normal(c, 0) to the last bit, fewer operations
inline Vec3 quad_centre_normal(const Quad& c) {
    // the tangents' weights at the centre are ±¼ (exact), so the sums match quad_normal's
    const Vec3 t1 = 0.25 * (((c[1] - c[0]) + c[2]) - c[3]);
    const Vec3 t2 = 0.25 * (((-c[0] - c[1]) + c[2]) + c[3]);
    return t1.cross(t2).normalized();
}

/// closest point of the face's bilinear surface to p (natural coordinates not clamped)
struct Projection {
    Vec2 xi = Vec2::Zero();     ///< natural coordinates of the foot point
    Vec3 point = Vec3::Zero();  ///< the foot point, m
    Vec3 normal = Vec3::UnitZ();///< outward unit normal there
};
Projection project(const Quad& c, const Vec3& p, Vec2 start = Vec2::Zero());

/// A face that is a parallelogram, x(ξ,η) = o + ξ·a + η·b exactly: projection in closed form.
struct ParallelogramFrame {
    bool valid = false;          ///< false: the face is not a parallelogram (use project())
    Vec3 o = Vec3::Zero();       ///< centre, m
    Vec3 a = Vec3::Zero();       ///< ∂x/∂ξ, m
    Vec3 b = Vec3::Zero();       ///< ∂x/∂η, m
    Vec3 n = Vec3::UnitZ();      ///< outward unit normal
    double g11 = 0, g12 = 0, g22 = 0, det = 1;   ///< metric a·a, a·b, b·b and its determinant, m², m⁴
    /// the frame of a face (valid only for a parallelogram)
    static ParallelogramFrame of(const Quad& c);
    /// the point at (ξ, η), m
    Vec3 point(const Vec2& xi) const { return o + xi[0] * a + xi[1] * b; }
    /// the closest point of the face's plane to p
    Projection project(const Vec3& p) const {
        const Vec3 r = p - o;
        const double r1 = a.dot(r), r2 = b.dot(r);
        Projection pr;
        pr.xi = Vec2((g22 * r1 - g12 * r2) / det, (g11 * r2 - g12 * r1) / det);
        pr.point = point(pr.xi);
        pr.normal = n;
        return pr;
    }
};

/// a hitting point of a face: natural coordinates and tributary area
struct HitPoint {
    Vec2 xi = Vec2::Zero();   ///< natural coordinates on the hitting face
    double area = 0.0;        ///< tributary area, m² (the face's points sum to its area)
};

/// the face corners plus a regular grid of virtual points no farther apart than `spacing` (m);
/// tributary areas by the trapezoid rule
std::vector<HitPoint> hit_grid(const Quad& c, double spacing);

/// points of hit_grid along ξ and along η
std::array<int, 2> hit_grid_counts(const Quad& c, double spacing);

/// area of the face, m²
double quad_area(const Quad& c);

}  // namespace cairn::dem
