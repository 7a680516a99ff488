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

std::array<double, 4> quad_weights(const Vec2& xi) {
    std::array<double, 4> w;
    for (int i = 0; i < 4; ++i) w[i] = 0.25 * (1 + kSign[i][0] * xi[0]) * (1 + kSign[i][1] * xi[1]);
    return w;
}

Vec3 quad_point(const Quad& c, const Vec2& xi) {
    auto w = quad_weights(xi);
    return w[0] * c[0] + w[1] * c[1] + w[2] * c[2] + w[3] * c[3];
}

Vec3 quad_normal(const Quad& c, const Vec2& xi) {
    Vec3 t1, t2;
    tangents(c, xi, t1, t2);
    return t1.cross(t2).normalized();
}

Projection project(const Quad& c, const Vec3& p, Vec2 start) {
    // Gauss-Newton on |x(ξ,η) - p|²: exact in one step for a parallelogram
    Vec2 xi = start;
    for (int it = 0; it < 6; ++it) {
        Vec3 t1, t2;
        tangents(c, xi, t1, t2);
        Vec3 r = quad_point(c, xi) - p;
        Eigen::Matrix2d jtj;
        jtj << t1.dot(t1), t1.dot(t2), t1.dot(t2), t2.dot(t2);
        Vec2 step = -jtj.ldlt().solve(Vec2(t1.dot(r), t2.dot(r)));
        xi += step;
        if (step.squaredNorm() < 1e-26) break;
    }
    Projection pr;
    pr.xi = xi;
    pr.point = quad_point(c, xi);
    pr.normal = quad_normal(c, xi);
    return pr;
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

std::vector<HitPoint> hit_grid(const Quad& c, double spacing) {
    double len_xi = std::max((c[1] - c[0]).norm(), (c[2] - c[3]).norm());
    double len_eta = std::max((c[3] - c[0]).norm(), (c[2] - c[1]).norm());
    auto count = [&](double len) { return std::max(2, int(std::ceil(len / spacing - 1e-9)) + 1); };
    int nu = count(len_xi), nv = count(len_eta);
    double du = 2.0 / (nu - 1), dv = 2.0 / (nv - 1);
    std::vector<HitPoint> pts;
    pts.reserve(nu * nv);
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
