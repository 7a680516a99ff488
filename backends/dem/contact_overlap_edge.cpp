#include "contact_overlap_edge.hpp"

#include <algorithm>
#include <cmath>

namespace cairn::dem {

EdgeForce edge_force(const ClipPolygon& poly, int i, const Vec3& c, const Vec3& n, const Affine& g,
                     const Vec3& slope, double kn, const Affine* depth) {
    EdgeForce e;
    const Vec3& p0 = poly.p[size_t(i)];
    const Vec3& p1 = poly.p[size_t((i + 1) % poly.n)];
    // the polygon lies behind the plane: heights below zero are rounding
    const double h0 = std::max(0.0, n.dot(c - p0)), h1 = std::max(0.0, n.dot(c - p1));
    const double length = ((p1 + h1 * n) - (p0 + h0 * n)).norm();
    const double d0 = depth ? std::max(0.0, (*depth)(p0)) : h0, d1 = depth ? std::max(0.0, (*depth)(p1)) : h1;
    // d is linear along the edge: ∫d² ds and ∫p·d² ds in closed form (Bernstein moments)
    const double w0 = d0 * d0 / 4.0 + d0 * d1 / 6.0 + d1 * d1 / 12.0;
    const double w1 = d0 * d0 / 12.0 + d0 * d1 / 6.0 + d1 * d1 / 4.0;
    e.d2 = length * (w0 + w1);
    if (!(e.d2 > 0.0)) return e;
    e.point = (w0 * p0 + w1 * p1) / (w0 + w1);
    // g = 0 moves along the plane at |∇φ| per unit of g, φ(x) = a_t·x − a_n·d(x) + b its trace
    const double a_n = g.a.dot(n);
    const Vec3 grad = g.a - a_n * n - a_n * slope;
    const double gn = grad.norm();
    if (!(gn > 1e-9 * g.a.norm())) return e;   // g = 0 parallel to the hitting face: no trace to move
    e.offset_gradient = 0.5 * kn * e.d2 / gn;
    e.force = -e.offset_gradient * g.a;
    return e;
}

}  // namespace cairn::dem
