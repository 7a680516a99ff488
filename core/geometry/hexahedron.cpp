#include "geometry/hexahedron.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cairn {

const std::array<std::array<int, 3>, 8> kCornerSigns = {{
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1},
}};

const std::array<std::array<int, 4>, 6> kFaceCorners = {{
    {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7},
}};

double shortest_edge(const Corners& c) {
    double e = 1e300;
    for (const auto& f : kFaceCorners)
        for (int i = 0; i < 4; ++i) e = std::min(e, (c[f[(i + 1) % 4]] - c[f[i]]).norm());
    return e;
}

Corners box_corners(const Vec3& size) {
    Corners c;
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k) c[i][k] = 0.5 * size[k] * kCornerSigns[i][k];
    return c;
}

// shape function values of the 8 corners at natural coordinates
static std::array<double, 8> shape(const Vec3& r) {
    std::array<double, 8> n;
    for (int i = 0; i < 8; ++i)
        n[i] = 0.125 * (1 + kCornerSigns[i][0] * r[0]) * (1 + kCornerSigns[i][1] * r[1]) *
               (1 + kCornerSigns[i][2] * r[2]);
    return n;
}

// jacobian ∂x/∂(ξ,η,ζ) of the trilinear map
static Mat3 jacobian(const Corners& c, const Vec3& r) {
    Mat3 j = Mat3::Zero();
    for (int i = 0; i < 8; ++i) {
        const auto& s = kCornerSigns[i];
        Vec3 d(0.125 * s[0] * (1 + s[1] * r[1]) * (1 + s[2] * r[2]),
               0.125 * s[1] * (1 + s[0] * r[0]) * (1 + s[2] * r[2]),
               0.125 * s[2] * (1 + s[0] * r[0]) * (1 + s[1] * r[1]));
        j += c[i] * d.transpose();
    }
    return j;
}

Vec3 trilinear_point(const Corners& c, const Vec3& natural) {
    auto n = shape(natural);
    Vec3 p = Vec3::Zero();
    for (int i = 0; i < 8; ++i) p += n[i] * c[i];
    return p;
}

MassProperties mass_properties(const Corners& c, double density) {
    // 3-point Gauss per direction: the integrand x·x·det J has degree ≤ 4 per variable
    const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
    const double w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    double vol = 0.0;
    Vec3 first = Vec3::Zero();
    Mat3 second = Mat3::Zero();
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            for (int k = 0; k < 3; ++k) {
                Vec3 r(g[a], g[b], g[k]);
                double dv = w[a] * w[b] * w[k] * jacobian(c, r).determinant();
                Vec3 x = trilinear_point(c, r);
                vol += dv;
                first += dv * x;
                second += dv * x * x.transpose();
            }
    MassProperties mp;
    mp.volume = vol;
    mp.mass = density * vol;
    mp.centre = first / vol;
    // second moment about the centre, then I = tr(S)·1 - S
    Mat3 s = density * (second - vol * mp.centre * mp.centre.transpose());
    mp.inertia = s.trace() * Mat3::Identity() - s;
    return mp;
}

std::string convexity_problem(const Corners& c) {
    double diameter = 0.0;
    for (int i = 0; i < 8; ++i)
        for (int j = i + 1; j < 8; ++j) diameter = std::max(diameter, (c[i] - c[j]).norm());
    if (!(diameter > 0.0)) return "all corners coincide";
    const double tol = 1e-9 * diameter;
    std::ostringstream why;
    for (int i = 0; i < 8; ++i) {
        Vec3 r(kCornerSigns[i][0], kCornerSigns[i][1], kCornerSigns[i][2]);
        if (!(jacobian(c, r).determinant() > 0.0)) {
            why << "corner " << i << " has a non-positive volume jacobian (corners out of hex8 order, "
                << "inverted or degenerate)";
            return why.str();
        }
    }
    for (int f = 0; f < 6; ++f) {
        const auto& fc = kFaceCorners[f];
        Vec3 n = (c[fc[1]] - c[fc[0]]).cross(c[fc[3]] - c[fc[0]]);
        n += (c[fc[3]] - c[fc[2]]).cross(c[fc[1]] - c[fc[2]]);
        if (!(n.norm() > 0.0)) {
            why << "face " << f << " has zero area";
            return why.str();
        }
        n.normalize();
        Vec3 centre = 0.25 * (c[fc[0]] + c[fc[1]] + c[fc[2]] + c[fc[3]]);
        for (int k = 0; k < 4; ++k) {
            double warp = std::abs(n.dot(c[fc[k]] - centre));
            if (warp > 1e-6 * diameter) {
                why << "face " << f << " is not planar (corner " << fc[k] << " is " << warp
                    << " m off its plane)";
                return why.str();
            }
        }
        for (int i = 0; i < 8; ++i)
            if (n.dot(c[i] - centre) > tol) {
                why << "not convex: corner " << i << " lies outside the plane of face " << f;
                return why.str();
            }
    }
    return {};
}

}  // namespace cairn
