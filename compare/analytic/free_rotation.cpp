#include "free_rotation.hpp"

#include <Eigen/Cholesky>

namespace cairn::oracle {

namespace {

/// the derivative of (q, ω): q̇ = ½ q ⊗ (0, ω), ω̇ = I⁻¹(−ω × Iω)
struct Deriv {
    Eigen::Vector4d dq;   // (w, x, y, z)
    Vec3 dw;
};

Eigen::Vector4d coeffs(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }
Quat quat(const Eigen::Vector4d& c) { return Quat(c[0], c[1], c[2], c[3]); }

Deriv derivative(const Eigen::LDLT<Mat3>& inv, const Mat3& inertia, const Eigen::Vector4d& qc, const Vec3& w) {
    const Quat q = quat(qc), rate = q * Quat(0.0, w.x(), w.y(), w.z());
    return {0.5 * coeffs(rate), inv.solve(-w.cross(inertia * w))};
}

}  // namespace

std::vector<FreeRotation::State> FreeRotation::states(const State& start, const std::vector<double>& times) const {
    const Eigen::LDLT<Mat3> inv(inertia);
    Eigen::Vector4d q = coeffs(start.q);
    Vec3 w = start.omega_body;
    double t = 0.0;
    // one RK4 step of length h
    auto advance = [&](double h) {
        const Deriv k1 = derivative(inv, inertia, q, w);
        const Deriv k2 = derivative(inv, inertia, q + 0.5 * h * k1.dq, w + 0.5 * h * k1.dw);
        const Deriv k3 = derivative(inv, inertia, q + 0.5 * h * k2.dq, w + 0.5 * h * k2.dw);
        const Deriv k4 = derivative(inv, inertia, q + h * k3.dq, w + h * k3.dw);
        q += h / 6.0 * (k1.dq + 2.0 * k2.dq + 2.0 * k3.dq + k4.dq);
        w += h / 6.0 * (k1.dw + 2.0 * k2.dw + 2.0 * k3.dw + k4.dw);
        q.normalize();
        t += h;
    };
    std::vector<State> out;
    out.reserve(times.size());
    for (double target : times) {
        while (t + step < target) advance(step);
        if (target > t) advance(target - t);
        out.push_back({quat(q), w});
    }
    return out;
}

double FreeRotation::energy(const State& s) const { return 0.5 * s.omega_body.dot(inertia * s.omega_body); }

Vec3 FreeRotation::momentum(const State& s) const { return s.q * (inertia * s.omega_body); }

}  // namespace cairn::oracle
