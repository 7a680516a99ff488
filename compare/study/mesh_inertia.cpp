#include "study/mesh_inertia.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace cairn::study {

namespace {

using Mat8 = Eigen::Matrix<double, 8, 8>;

/// shape function of corner a at natural coordinates q
double shape(int a, const Vec3& q) {
    const auto& s = kCornerSigns[a];
    return 0.125 * (1 + s[0] * q.x()) * (1 + s[1] * q.y()) * (1 + s[2] * q.z());
}

/// det of the trilinear map's Jacobian at q
double jacobian_det(const Corners& c, const Vec3& q) {
    Mat3 j = Mat3::Zero();
    for (int a = 0; a < 8; ++a) {
        const auto& s = kCornerSigns[a];
        const Vec3 dn(0.125 * s[0] * (1 + s[1] * q.y()) * (1 + s[2] * q.z()),
                      0.125 * s[1] * (1 + s[0] * q.x()) * (1 + s[2] * q.z()),
                      0.125 * s[2] * (1 + s[0] * q.x()) * (1 + s[1] * q.y()));
        j += c[a] * dn.transpose();
    }
    return j.determinant();
}

/// 3-point Gauss rule on [-1, 1]: exact to degree 5 (N_a N_b det J is degree ≤ 4 per variable)
constexpr std::array<double, 3> kPts{-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr std::array<double, 3> kWts{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

/// ∫ρ N_a N_b dV of one element
Mat8 consistent_mass(const Corners& c, double density) {
    Mat8 m = Mat8::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) {
                const Vec3 q(kPts[i], kPts[j], kPts[k]);
                const double w = kWts[i] * kWts[j] * kWts[k] * jacobian_det(c, q) * density;
                std::array<double, 8> n;
                for (int a = 0; a < 8; ++a) n[a] = shape(a, q);
                for (int a = 0; a < 8; ++a)
                    for (int b = 0; b < 8; ++b) m(a, b) += w * n[a] * n[b];
            }
    return m;
}

/// inertia tensor of a point mass m at r from the centre
Mat3 point_inertia(const Vec3& r, double m) { return m * (r.squaredNorm() * Mat3::Identity() - r * r.transpose()); }

}  // namespace

MeshInertia mesh_inertia(const Corners& corners, double density, const std::array<int, 3>& d,
                         MassScheme scheme) {
    const int nx = d[0], ny = d[1], nz = d[2];
    auto node = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
    std::vector<Vec3> x((nx + 1) * (ny + 1) * (nz + 1));
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i)
                x[node(i, j, k)] = trilinear_point(corners, Vec3(-1.0 + 2.0 * i / nx, -1.0 + 2.0 * j / ny,
                                                                 -1.0 + 2.0 * k / nz));
    std::vector<double> lumped(x.size(), 0.0);
    struct Entry { int a, b; double m; };
    std::vector<Entry> consistent;
    std::vector<std::pair<Vec3, double>> centres;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                std::array<int, 8> e;
                Corners c;
                for (int a = 0; a < 8; ++a) {
                    const auto& s = kCornerSigns[a];
                    e[a] = node(i + (s[0] > 0), j + (s[1] > 0), k + (s[2] > 0));
                    c[a] = x[e[a]];
                }
                const Mat8 me = consistent_mass(c, density);
                for (int a = 0; a < 8; ++a) {
                    lumped[e[a]] += me.row(a).sum();
                    for (int b = 0; b < 8; ++b) consistent.push_back({e[a], e[b], me(a, b)});
                }
                centres.emplace_back(trilinear_point(c, Vec3::Zero()), me.sum());
            }
    MeshInertia out;
    for (size_t n = 0; n < x.size(); ++n) {
        out.mass += lumped[n];
        out.centre += lumped[n] * x[n];
    }
    out.centre /= out.mass;
    // the exact inertia, integrated directly over the undivided hexahedron
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) {
                const Vec3 q(kPts[i], kPts[j], kPts[k]);
                const double w = kWts[i] * kWts[j] * kWts[k] * jacobian_det(corners, q) * density;
                out.exact += point_inertia(trilinear_point(corners, q) - out.centre, w);
            }
    switch (scheme) {
        case MassScheme::lumped:
            for (size_t n = 0; n < x.size(); ++n) out.inertia += point_inertia(x[n] - out.centre, lumped[n]);
            break;
        case MassScheme::consistent:
            for (const auto& t : consistent) {
                const Vec3 ra = x[t.a] - out.centre, rb = x[t.b] - out.centre;
                out.inertia += t.m * (ra.dot(rb) * Mat3::Identity() -
                                      0.5 * (ra * rb.transpose() + rb * ra.transpose()));
            }
            break;
        case MassScheme::barycentre:
            for (const auto& [c, m] : centres) out.inertia += point_inertia(c - out.centre, m);
            out.inertia += 1e-3 * out.exact;
            break;
        case MassScheme::corrected: out.inertia = out.exact; break;
    }
    return out;
}

double inertia_about_line(const MeshInertia& mi, const Vec3& axis, const Vec3& point) {
    const Vec3 r = mi.centre - point;
    const double d2 = r.squaredNorm() - std::pow(r.dot(axis), 2);
    return axis.dot(mi.inertia * axis) + mi.mass * d2;
}

Vec3 rocking_edge_point(const Corners& corners, const Vec3& axis) {
    const Vec3 across = axis.cross(Vec3::UnitZ()).normalized();
    // the bottom face's corner farthest across (ties: the first)
    Vec3 best = corners[0];
    for (int a = 0; a < 4; ++a)
        if (corners[a].dot(across) > best.dot(across) + 1e-12) best = corners[a];
    return best;
}

double closed_form_edge_ratio(MassScheme scheme, int n, bool with_floor) {
    const double n2 = double(n) * n;
    switch (scheme) {
        case MassScheme::barycentre: return 1.0 - 1.0 / (4.0 * n2) + (with_floor ? 0.25e-3 : 0.0);
        case MassScheme::lumped: return 1.0 + 1.0 / (2.0 * n2);
        default: return 1.0;
    }
}

double closed_form_centre_ratio(MassScheme scheme, int n, bool with_floor) {
    const double n2 = double(n) * n;
    switch (scheme) {
        case MassScheme::barycentre: return 1.0 - 1.0 / n2 + (with_floor ? 1e-3 : 0.0);
        case MassScheme::lumped: return 1.0 + 2.0 / n2;
        default: return 1.0;
    }
}

}  // namespace cairn::study
