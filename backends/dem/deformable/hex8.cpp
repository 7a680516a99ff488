#include "dem/deformable/hex8.hpp"

#include <cmath>

namespace cairn::dem {

std::array<double, 8> hex8_shape(const Vec3& r) {
    std::array<double, 8> n;
    for (int a = 0; a < 8; ++a) {
        const auto& s = kCornerSigns[a];
        n[a] = 0.125 * (1 + s[0] * r[0]) * (1 + s[1] * r[1]) * (1 + s[2] * r[2]);
    }
    return n;
}

Mat83 hex8_dshape(const Vec3& r) {
    Mat83 d;
    for (int a = 0; a < 8; ++a) {
        const auto& s = kCornerSigns[a];
        d(a, 0) = 0.125 * s[0] * (1 + s[1] * r[1]) * (1 + s[2] * r[2]);
        d(a, 1) = 0.125 * s[1] * (1 + s[0] * r[0]) * (1 + s[2] * r[2]);
        d(a, 2) = 0.125 * s[2] * (1 + s[0] * r[0]) * (1 + s[1] * r[1]);
    }
    return d;
}

const std::array<Vec3, 8>& hex8_gauss_points() {
    static const std::array<Vec3, 8> pts = [] {
        std::array<Vec3, 8> p;
        const double g = 1.0 / std::sqrt(3.0);
        for (int a = 0; a < 8; ++a)
            p[a] = Vec3(g * kCornerSigns[a][0], g * kCornerSigns[a][1], g * kCornerSigns[a][2]);
        return p;
    }();
    return pts;
}

Hex8Reference hex8_reference(const Corners& x_ref) {
    Hex8Reference ref;
    Mat83 x;
    for (int a = 0; a < 8; ++a) x.row(a) = x_ref[a].transpose();
    for (int g = 0; g < 8; ++g) {
        Mat83 dn = hex8_dshape(hex8_gauss_points()[g]);
        Mat3 j = x.transpose() * dn;   // ∂X/∂ξ
        ref.weight[g] = j.determinant();
        ref.dndx[g] = dn * j.inverse();
    }
    return ref;
}

Lame lame(double young, double poisson) {
    Lame l;
    l.lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
    l.mu = young / (2 * (1 + poisson));
    return l;
}

double hex8_internal_force(const Hex8Reference& ref, const Lame& lm, const Mat83& x, Mat83& f, double beta,
                           const Mat83* v, double* damping_power) {
    double energy = 0.0;
    for (int g = 0; g < 8; ++g) {
        const Mat83& dn = ref.dndx[g];
        const Mat3 F = x.transpose() * dn;                       // deformation gradient
        const Mat3 E = 0.5 * (F.transpose() * F - Mat3::Identity());
        const double trE = E.trace();
        Mat3 S = 2.0 * lm.mu * E;
        S.diagonal().array() += lm.lambda * trE;                 // second Piola–Kirchhoff stress
        energy += ref.weight[g] * (0.5 * lm.lambda * trE * trE + lm.mu * E.squaredNorm());
        if (beta > 0.0 && v) {
            // Kelvin–Voigt: viscous stress β·C:Ė, zero for rigid motions
            const Mat3 Fdot = v->transpose() * dn;
            const Mat3 Edot = 0.5 * (F.transpose() * Fdot + Fdot.transpose() * F);
            Mat3 Sv = 2.0 * lm.mu * Edot;
            Sv.diagonal().array() += lm.lambda * Edot.trace();
            Sv *= beta;
            S += Sv;
            if (damping_power) *damping_power += ref.weight[g] * (Sv.array() * Edot.array()).sum();
        }
        f.noalias() += ref.weight[g] * dn * (F * S).transpose();  // f_a = w·P·∂N_a/∂X
    }
    return energy;
}

Eigen::Matrix<double, 8, 8> hex8_consistent_mass(const Hex8Reference& ref, double density) {
    Eigen::Matrix<double, 8, 8> m = Eigen::Matrix<double, 8, 8>::Zero();
    for (int g = 0; g < 8; ++g) {
        auto n = hex8_shape(hex8_gauss_points()[g]);
        Eigen::Matrix<double, 8, 1> nv = Eigen::Map<Eigen::Matrix<double, 8, 1>>(n.data());
        m += density * ref.weight[g] * nv * nv.transpose();
    }
    return m;
}

Mat24 hex8_stiffness(const Hex8Reference& ref, const Lame& lm) {
    // linear elasticity at the reference state: K = Σ w·Bᵀ D B
    Mat24 k = Mat24::Zero();
    Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
    d.topLeftCorner<3, 3>().setConstant(lm.lambda);
    d.diagonal().head<3>().array() += 2 * lm.mu;
    d.diagonal().tail<3>().setConstant(lm.mu);
    for (int g = 0; g < 8; ++g) {
        Eigen::Matrix<double, 6, 24> b = Eigen::Matrix<double, 6, 24>::Zero();
        for (int a = 0; a < 8; ++a) {
            const double dx = ref.dndx[g](a, 0), dy = ref.dndx[g](a, 1), dz = ref.dndx[g](a, 2);
            b(0, 3 * a) = dx;
            b(1, 3 * a + 1) = dy;
            b(2, 3 * a + 2) = dz;
            b(3, 3 * a) = dy, b(3, 3 * a + 1) = dx;
            b(4, 3 * a + 1) = dz, b(4, 3 * a + 2) = dy;
            b(5, 3 * a) = dz, b(5, 3 * a + 2) = dx;
        }
        k += ref.weight[g] * b.transpose() * d * b;
    }
    return k;
}

}  // namespace cairn::dem
