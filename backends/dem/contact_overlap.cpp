#include "contact_overlap.hpp"

#include <cmath>

namespace cairn::dem {

void clip(ClipPolygon& poly, const Affine& g, int label) {
    if (poly.n == 0) return;
    std::array<double, ClipPolygon::kMaxVertices> val;
    bool all_in = true, all_out = true;
    for (int i = 0; i < poly.n; ++i) {
        val[i] = g(poly.p[i]);
        all_in = all_in && val[i] >= 0.0;
        all_out = all_out && val[i] < 0.0;
    }
    if (all_in) return;
    if (all_out) {
        poly.n = 0;
        return;
    }
    ClipPolygon out;
    // each vertex kept carries on its edge's label; a cut point leaving the region starts the
    // edge along g = 0 (labelled by g), one entering it carries on the edge it lies on
    const unsigned char cut = static_cast<unsigned char>(label + 1);
    for (int i = 0; i < poly.n; ++i) {
        const int j = (i + 1) % poly.n;
        const bool in_i = val[i] >= 0.0, in_j = val[j] >= 0.0;
        if (in_i && out.n < ClipPolygon::kMaxVertices) {
            out.by[out.n] = poly.by[i];
            out.p[out.n++] = poly.p[i];
        }
        if (in_i != in_j && out.n < ClipPolygon::kMaxVertices) {
            // the edge crosses g = 0: one cut point, linear along the edge
            const double s = val[i] / (val[i] - val[j]);
            out.by[out.n] = in_i ? cut : poly.by[i];
            out.p[out.n++] = poly.p[i] + s * (poly.p[j] - poly.p[i]);
        }
    }
    // only the vertices in use (a whole polygon is 24 of them)
    poly.n = out.n;
    for (int i = 0; i < out.n; ++i) poly.p[i] = out.p[i], poly.by[i] = out.by[i];
}

OverlapIntegrals fan_integrals(const Vec3* x, const double* h, const double* d, const Vec3* m, int count, const Vec3& n) {
    OverlapIntegrals r;
    // fan from vertex 0; over a triangle with barycentric λ, ∫λiλj dA = A(1 + δij)/12
    for (int i = 1; i + 1 < count; ++i) {
        const double a = 0.5 * (x[i] - x[0]).cross(x[i + 1] - x[0]).dot(n);
        const double s = d[0] + d[i] + d[i + 1];
        const double q = d[0] * d[0] + d[i] * d[i] + d[i + 1] * d[i + 1];
        const Vec3 sx = m[0] + m[i] + m[i + 1];
        const Vec3 xd = d[0] * m[0] + d[i] * m[i] + d[i + 1] * m[i + 1];
        // a·∇h of the triangle, ∇λ_k = n × (opposite edge) / 2a
        const Vec3 a_grad = 0.5 * n.cross(h[0] * (x[i + 1] - x[i]) + h[i] * (x[0] - x[i + 1]) + h[i + 1] * (x[i] - x[0]));
        r.tilt += a_grad * (s * s + q) / 12.0;
        r.slope += a_grad;
        r.area += a;
        r.d1 += a * s / 3.0;
        r.d2 += a * (s * s + q) / 12.0;
        r.moment += a * (xd + sx * s) / 12.0;
        r.first += a * sx / 3.0;
    }
    // a hitting cell seen from the target runs clockwise: the signs of the fan follow its turn
    if (r.area < 0.0) {
        r.area = -r.area;
        r.d1 = -r.d1;
        r.d2 = -r.d2;
        r.moment = -r.moment;
        r.first = -r.first;
        r.tilt = -r.tilt;
        r.slope = -r.slope;
    }
    if (r.area > 0.0) r.slope /= r.area;
    return r;
}

OverlapIntegrals integrate_depth(const ClipPolygon& poly, const Vec3& c, const Vec3& n) {
    if (poly.n < 3) return OverlapIntegrals{};
    // projected vertices and their depths
    std::array<Vec3, ClipPolygon::kMaxVertices> x;
    std::array<double, ClipPolygon::kMaxVertices> d;
    for (int i = 0; i < poly.n; ++i) {
        d[i] = n.dot(c - poly.p[i]);
        x[i] = poly.p[i] + d[i] * n;
    }
    return fan_integrals(x.data(), d.data(), d.data(), x.data(), poly.n, n);
}

}  // namespace cairn::dem
