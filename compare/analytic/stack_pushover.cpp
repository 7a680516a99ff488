#include "stack_pushover.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace cairn::oracle {

namespace {

/// bed joint j's width: the narrower of the layers it joins (the base is wider than layer 0)
double joint_width(const std::vector<StackLayer>& l, size_t j) {
    return j == 0 ? l[0].width : std::min(l[j - 1].width, l[j].width);
}
double joint_depth(const std::vector<StackLayer>& l, size_t j) {
    return j == 0 ? l[0].depth : std::min(l[j - 1].depth, l[j].depth);
}

/// the resisting moment (N·m) of a no-tension Winkler joint of width b, depth d, stiffness kn
/// under the normal force n at relative rotation phi: linear while the whole joint is closed,
/// then n·(b/2 − a/3) with the closed length a = √(2n/(kn d φ))
double joint_moment(double phi, double n, double b, double d, double kn) {
    const double s = phi < 0 ? -1.0 : 1.0, p = std::abs(phi);
    if (p * kn * d * b * b <= 2.0 * n) return s * kn * d * b * b * b / 12.0 * p;
    const double a = std::sqrt(2.0 * n / (kn * d * p));
    return s * n * (0.5 * b - a / 3.0);
}

}  // namespace

double BlockStack::rigid_multiplier() const {
    double best = INFINITY;
    for (size_t j = 0; j < layers.size(); ++j) {
        double m = 0.0, mz = 0.0, z = 0.0;
        for (size_t i = j; i < layers.size(); ++i) {
            m += layers[i].mass;
            mz += layers[i].mass * (z + 0.5 * layers[i].height);
            z += layers[i].height;
        }
        best = std::min(best, 0.5 * joint_width(layers, j) / (mz / m));
    }
    return best;
}

namespace {

struct PathPoint {
    double lambda = 0.0, top_rotation = 0.0;
};

/// continuation along the quasi-static path: base rotation φ0 given, (λ, φ1 … φn−1) solved
std::vector<PathPoint> winkler_path(const std::vector<StackLayer>& l, double g, double kn) {
    const size_t n = l.size();
    std::vector<double> zb(n + 1, 0.0), w(n), nforce(n, 0.0);
    for (size_t i = 0; i < n; ++i) zb[i + 1] = zb[i] + l[i].height, w[i] = l[i].mass * g;
    for (size_t j = n; j-- > 0;) nforce[j] = w[j] + (j + 1 < n ? nforce[j + 1] : 0.0);
    // residual of joint j's moment balance for joint rotations phi and multiplier lam
    auto residual = [&](const Eigen::VectorXd& phi, double lam) {
        Eigen::VectorXd r(n);
        std::vector<double> theta(n);
        double acc = 0.0;
        for (size_t k = 0; k < n; ++k) theta[k] = acc += phi[k];
        for (size_t j = 0; j < n; ++j) {
            double m = 0.0;
            for (size_t i = j; i < n; ++i) {
                double dx = 0.5 * l[i].height * theta[i];   // centroid i's lean over joint j
                for (size_t k = j; k < i; ++k) dx += l[k].height * theta[k];
                m += w[i] * (lam * (zb[i] + 0.5 * l[i].height - zb[j]) + dx);
            }
            r[j] = joint_moment(phi[j], nforce[j], joint_width(l, j), joint_depth(l, j), kn) - m;
        }
        return r;
    };
    std::vector<PathPoint> path;
    // unknowns x = (λ, φ1 … φn−1) for a given φ0
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    const double phi_end = 0.3, steps = 3000;
    for (int s = 1; s <= steps; ++s) {
        const double phi0 = phi_end * std::pow(double(s) / steps, 2.0);   // fine steps near zero
        auto full = [&](const Eigen::VectorXd& y) {
            Eigen::VectorXd phi(n);
            phi[0] = phi0;
            for (size_t k = 1; k < n; ++k) phi[k] = y[k];
            return residual(phi, y[0]);
        };
        for (int it = 0; it < 50; ++it) {
            const Eigen::VectorXd r = full(x);
            Eigen::MatrixXd jac(n, n);
            for (size_t c = 0; c < n; ++c) {
                Eigen::VectorXd y = x;
                const double h = 1e-9 * std::max(1.0, std::abs(x[c]));
                y[c] += h;
                jac.col(c) = (full(y) - r) / h;
            }
            const Eigen::VectorXd dx = jac.fullPivLu().solve(-r);
            x += dx;
            if (dx.norm() < 1e-13) break;
        }
        double top = phi0;
        for (size_t k = 1; k < n; ++k) top += x[k];
        path.push_back({x[0], top});
    }
    return path;
}

}  // namespace

double BlockStack::winkler_multiplier(double kn) const {
    double best = 0.0;
    for (const auto& p : winkler_path(layers, g, kn)) best = std::max(best, p.lambda);
    return best;
}

double BlockStack::winkler_peak_rotation(double kn) const {
    PathPoint best;
    for (const auto& p : winkler_path(layers, g, kn))
        if (p.lambda > best.lambda) best = p;
    return best.top_rotation;
}

double BlockStack::rigid_ramp_time(const std::function<double(double)>& lambda, double rotation, double until) const {
    // the monolith: mass m, centre (b, h) from the leading base edge, inertia i about that edge;
    // θ̈ = (m g/i)[λ(t)(h cos θ − b sin θ) − (b cos θ − h sin θ)], held at θ = 0 while that is < 0
    double m = 0.0, mz = 0.0, z = 0.0;
    for (const auto& l : layers) {
        m += l.mass;
        mz += l.mass * (z + 0.5 * l.height);
        z += l.height;
    }
    const double h = mz / m, b = 0.5 * layers[0].width;
    double i = 0.0;
    z = 0.0;
    for (const auto& l : layers) {   // own inertia + m·distance² to the edge
        const double zc = z + 0.5 * l.height;
        i += l.mass * (l.width * l.width + l.height * l.height) / 12.0 + l.mass * (b * b + zc * zc);
        z += l.height;
    }
    auto acc = [&](double t, double a) {
        const double torque = m * g * (lambda(t) * (h * std::cos(a) - b * std::sin(a)) - (b * std::cos(a) - h * std::sin(a)));
        return (a <= 0.0 && torque <= 0.0) ? 0.0 : torque / i;
    };
    const double dt = 1e-4;
    double t = 0.0, th = 0.0, w = 0.0;
    while (t < until) {
        const double k1a = w, k1w = acc(t, th);
        const double k2a = w + 0.5 * dt * k1w, k2w = acc(t + 0.5 * dt, th + 0.5 * dt * k1a);
        const double k3a = w + 0.5 * dt * k2w, k3w = acc(t + 0.5 * dt, th + 0.5 * dt * k2a);
        const double k4a = w + dt * k3w, k4w = acc(t + dt, th + dt * k3a);
        const double th_new = th + dt / 6.0 * (k1a + 2 * k2a + 2 * k3a + k4a);
        w += dt / 6.0 * (k1w + 2 * k2w + 2 * k3w + k4w);
        if (th_new <= 0.0) th = 0.0, w = std::max(0.0, w);   // resting on the base
        else th = th_new;
        t += dt;
        if (th >= rotation) return t;
    }
    return NAN;
}

}  // namespace cairn::oracle
