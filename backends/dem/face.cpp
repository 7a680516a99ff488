#include "face.hpp"

#include <algorithm>
#include <cmath>

namespace cairn::dem {

namespace {
const double kSign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

// tangents ∂x/∂ξ and ∂x/∂η
void tangents(const Quad& c, const Vec2& xi, Vec3& t1, Vec3& t2) {
    t1.setZero();
    t2.setZero();
    for (int i = 0; i < 4; ++i) {
        t1 += 0.25 * kSign[i][0] * (1 + kSign[i][1] * xi[1]) * c[i];
        t2 += 0.25 * kSign[i][1] * (1 + kSign[i][0] * xi[0]) * c[i];
    }
}
}  // namespace

Vec3 quad_normal(const Quad& c, const Vec2& xi) {
    Vec3 t1, t2;
    tangents(c, xi, t1, t2);
    return t1.cross(t2).normalized();
}

Projection project(const Quad& c, const Vec3& p, Vec2 start) {
    // Gauss-Newton on |x(ξ,η) - p|²: exact in one step for a parallelogram (no twist term)
    const Vec3 twist = c[0] - c[1] + c[2] - c[3];
    const bool parallelogram = twist.squaredNorm() <= 1e-24 * (c[2] - c[0]).squaredNorm();
    Vec2 xi = start;
    for (int it = 0; it < 6; ++it) {
        Vec3 t1, t2;
        tangents(c, xi, t1, t2);
        const Vec3 r = quad_point(c, xi) - p;
        const double g11 = t1.dot(t1), g12 = t1.dot(t2), g22 = t2.dot(t2), det = g11 * g22 - g12 * g12;
        const double r1 = t1.dot(r), r2 = t2.dot(r);
        const Vec2 step((g12 * r2 - g22 * r1) / det, (g12 * r1 - g11 * r2) / det);
        xi += step;
        if (parallelogram || step.squaredNorm() < 1e-26) break;
    }
    Projection pr;
    pr.xi = xi;
    pr.point = quad_point(c, xi);
    pr.normal = quad_normal(c, xi);
    return pr;
}

ParallelogramFrame ParallelogramFrame::of(const Quad& c) {
    ParallelogramFrame f;
    const Vec3 twist = c[0] - c[1] + c[2] - c[3];
    if (twist.squaredNorm() > 1e-24 * (c[2] - c[0]).squaredNorm()) return f;
    f.valid = true;
    f.o = 0.25 * (c[0] + c[1] + c[2] + c[3]);
    f.a = 0.5 * (c[1] - c[0]);
    f.b = 0.5 * (c[3] - c[0]);
    f.n = f.a.cross(f.b).normalized();
    f.g11 = f.a.dot(f.a);
    f.g12 = f.a.dot(f.b);
    f.g22 = f.b.dot(f.b);
    f.det = f.g11 * f.g22 - f.g12 * f.g12;
    return f;
}

double quad_area(const Quad& c) {
    // 2x2 Gauss: exact for the bilinear jacobian of a planar face
    const double g = 1.0 / std::sqrt(3.0);
    double a = 0.0;
    for (double u : {-g, g})
        for (double v : {-g, g}) {
            Vec3 t1, t2;
            tangents(c, Vec2(u, v), t1, t2);
            a += t1.cross(t2).norm();
        }
    return a;
}

std::array<int, 2> hit_grid_counts(const Quad& c, double spacing) {
    double len_xi = std::max((c[1] - c[0]).norm(), (c[2] - c[3]).norm());
    double len_eta = std::max((c[3] - c[0]).norm(), (c[2] - c[1]).norm());
    // in double, then clamped: a spacing far below the face size must not overflow the count
    // (check_build_size refuses such a grid before it is built)
    auto count = [&](double len) {
        const double n = std::ceil(len / spacing - 1e-9) + 1.0;
        return n >= 2.0 && n < 1e9 ? int(n) : (n >= 1e9 ? int(1e9) : 2);
    };
    return {count(len_xi), count(len_eta)};
}

std::vector<HitPoint> hit_grid(const Quad& c, double spacing) {
    const auto [nu, nv] = hit_grid_counts(c, spacing);
    double du = 2.0 / (nu - 1), dv = 2.0 / (nv - 1);
    std::vector<HitPoint> pts;
    pts.reserve(size_t(nu) * size_t(nv));
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            HitPoint h;
            h.xi = Vec2(-1 + i * du, -1 + j * dv);
            double wu = (i == 0 || i == nu - 1) ? 0.5 : 1.0;
            double wv = (j == 0 || j == nv - 1) ? 0.5 : 1.0;
            Vec3 t1, t2;
            tangents(c, h.xi, t1, t2);
            h.area = wu * wv * du * dv * t1.cross(t2).norm();
            pts.push_back(h);
        }
    return pts;
}

}  // namespace cairn::dem
