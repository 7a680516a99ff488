#pragma once
/// Geometry of the overlap scheme: a hitting sub-cell (a polygon on the hitting face) clipped by
/// affine constraints g(p) = a·p + b ≥ 0 (behind the target plane, over the target face, not
/// entering through another side), and the closed-form integrals of the penetration d over the
/// clipped polygon projected on the target plane (d is affine over a planar cell, so area × d at
/// the centroid and the first moment are exact).

#include <array>

#include "geometry/types.hpp"

namespace cairn::dem {

/// an affine function of a point, g(p) = a·p + b (units of a length)
struct Affine {
    Vec3 a = Vec3::Zero();   ///< gradient, dimensionless
    double b = 0.0;          ///< value at the origin, m
    double operator()(const Vec3& p) const { return a.dot(p) + b; }
};

/// a convex polygon of at most kMaxVertices vertices (a quadrilateral clipped by up to 16 planes)
struct ClipPolygon {
    static constexpr int kMaxVertices = 24;
    int n = 0;                                  ///< vertex count
    std::array<Vec3, kMaxVertices> p;           ///< vertices, m
    /// what made edge i (p[i] to p[i+1]): 0 the polygon as given, k + 1 the cut by constraint k
    std::array<unsigned char, kMaxVertices> by{};
};

/// keep the part of `poly` where g ≥ 0 (Sutherland–Hodgman; g is affine, so cut points are exact);
/// the edge the cut makes is labelled `label` (ClipPolygon::by: label + 1; −1: as given)
void clip(ClipPolygon& poly, const Affine& g, int label = -1);

/// the integrals of the penetration over a polygon projected on a target plane
struct OverlapIntegrals {
    double area = 0.0;             ///< projected area, m²
    double d1 = 0.0;               ///< ∫ d dA, m³
    double d2 = 0.0;               ///< ∫ d² dA, m⁴
    Vec3 moment = Vec3::Zero();    ///< ∫ x d dA over the projected points x, m⁴
    Vec3 first = Vec3::Zero();     ///< ∫ x dA over the projected points x, m³
    Vec3 tilt = Vec3::Zero();      ///< ∫ d²·∇d dA, ∇d the depth's gradient along the plane, m⁴
    Vec3 slope = Vec3::Zero();     ///< ∫ ∇d dA / area: the mean gradient of the depth along the plane
    /// the pressure centre ∫x(d + η)/∫(d + η) with η = 1e-12 m: ∫x·d/∫d wherever the depth is
    /// above rounding; for faces just touching (d ~ 1e-17 m of either sign, ∫d a rounding
    /// residue) the area's centroid instead of a quotient of residues anywhere in space, m
    Vec3 pressure_centre() const {
        constexpr double eta = 1e-12;
        return (moment + eta * first) / (d1 + eta * area);
    }
    /// where the normal force kn·∫d dA along n acts so that it is the gradient of ½kn∫d² dA: the
    /// pressure centre moved by −½∫d²∇d dA / ∫d dA along the plane (a face tilted to the target
    /// plane: its projected area changes as it turns, a couple ½kn·n × ∫d²∇d dA; docs/dem.md), m
    Vec3 action_point() const {
        constexpr double eta = 1e-12;
        return (moment + eta * first - 0.5 * tilt) / (d1 + eta * area);
    }
};

/// integrals of d = n·(c − p) over the projection of `poly` on the plane through c with unit
/// normal n (triangle fan; exact for a planar polygon, since d is affine)
OverlapIntegrals integrate_depth(const ClipPolygon& poly, const Vec3& c, const Vec3& n);

/// the triangle fan behind integrate_depth: over a planar polygon of `count` vertices projected at
/// x on a plane of unit normal n, heights h behind that plane (the slope and tilt are those of h),
/// a depth d affine over the polygon (d1, d2) and points m carried in the moments (the projected
/// points, or the polygon's own)
OverlapIntegrals fan_integrals(const Vec3* x, const double* h, const double* d, const Vec3* m, int count, const Vec3& n);

}  // namespace cairn::dem
