#include "arch_lateral.hpp"

#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace cairn::oracle {

namespace {

/// a·p ≤ b in the unknowns p = (X, Z, M) of the left springing's reaction
struct Constraint {
    std::array<double, 3> a;
    double b;
};

/// the joints' constraints (R = 1, per unit depth and ρ·g): the force across joint k, from the
/// voussoirs left of it onto those right of it, is F = (X, Z) + Σ λ·w_i, −w_i) with moment
/// M + Σ c_i × B_i about the centre; it crosses the radial joint at angle α (unit vector u) at
/// radius s = M_k / (u × F) with u × F < 0 in compression: re·(u × F) ≤ M_k ≤ ri·(u × F)
std::vector<Constraint> joint_constraints(int n, double t, double lambda) {
    const double ri = 1.0 - 0.5 * t, re = 1.0 + 0.5 * t;
    // F_k = Fp·p + Fc, M_k = Mp·p + Mc
    std::array<double, 3> fx{1, 0, 0}, fz{0, 1, 0}, mp{0, 0, 1};
    double fxc = 0.0, fzc = 0.0, mc = 0.0;
    std::vector<Constraint> out;
    const double step = M_PI / n;
    for (int k = 0; k <= n; ++k) {
        const double alpha = M_PI - k * step, ux = std::cos(alpha), uz = std::sin(alpha);
        std::array<double, 3> cp;   // u × F = ux·Fz − uz·Fx
        for (int i = 0; i < 3; ++i) cp[i] = ux * fz[i] - uz * fx[i];
        const double cc = ux * fzc - uz * fxc;
        Constraint lower, upper;   // re·c − M ≤ 0 and M − ri·c ≤ 0
        for (int i = 0; i < 3; ++i) {
            lower.a[i] = re * cp[i] - mp[i];
            upper.a[i] = mp[i] - ri * cp[i];
        }
        lower.b = mc - re * cc;
        upper.b = ri * cc - mc;
        out.push_back(lower);
        out.push_back(upper);
        if (k == n) break;
        // voussoir k: the ring sector between α and α − π/N, area π/N·t, its centroid at radius ρ
        const double mid = alpha - 0.5 * step, w = step * t;
        const double rho = (2.0 / 3.0) * (re * re * re - ri * ri * ri) / (re * re - ri * ri) *
                           std::sin(0.5 * step) / (0.5 * step);
        const double cx = rho * std::cos(mid), cz = rho * std::sin(mid), bx = lambda * w, bz = -w;
        fxc += bx;
        fzc += bz;
        mc += cx * bz - cz * bx;
    }
    return out;
}

/// the point where the planes of three constraints meet; false when they are (nearly) dependent
bool solve3(const Constraint& p, const Constraint& q, const Constraint& r, Eigen::Vector3d& x) {
    Eigen::Matrix3d m;
    m << p.a[0], p.a[1], p.a[2], q.a[0], q.a[1], q.a[2], r.a[0], r.a[1], r.a[2];
    if (std::abs(m.determinant()) < 1e-14) return false;
    x = m.partialPivLu().solve(Eigen::Vector3d(p.b, q.b, r.b));
    return true;
}

}  // namespace

bool ArchUnderLateralLoad::thrust_line_fits(double lambda) const {
    const auto cs = joint_constraints(voussoirs, thickness, lambda);
    // the feasible set is a bounded polyhedron (the joints bound the reaction): it is empty unless
    // one of its vertices, an intersection of three constraint planes, satisfies every constraint
    const double tol = 1e-12;
    Eigen::Vector3d x;
    for (size_t i = 0; i < cs.size(); ++i)
        for (size_t j = i + 1; j < cs.size(); ++j)
            for (size_t k = j + 1; k < cs.size(); ++k) {
                if (!solve3(cs[i], cs[j], cs[k], x)) continue;
                bool ok = true;
                for (const auto& c : cs)
                    if (c.a[0] * x[0] + c.a[1] * x[1] + c.a[2] * x[2] > c.b + tol) {
                        ok = false;
                        break;
                    }
                if (ok) return true;
            }
    return false;
}

double ArchUnderLateralLoad::collapse_acceleration() const {
    if (!thrust_line_fits(0.0)) return 0.0;
    double lo = 0.0, hi = 1.0;
    while (!(thrust_line_fits(lo) && !thrust_line_fits(hi)) && hi < 64.0) hi *= 2.0;
    while (hi - lo > 1e-6) {
        const double mid = 0.5 * (lo + hi);
        (thrust_line_fits(mid) ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace cairn::oracle
