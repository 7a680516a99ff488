#include "stack_pushover.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>

#include "winkler_joint.hpp"

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
    const double along = std::abs(std::cos(push_angle)), across = std::abs(std::sin(push_angle));
    double best = INFINITY;
    for (size_t j = 0; j < layers.size(); ++j) {
        double m = 0.0, mz = 0.0, z = 0.0;
        for (size_t i = j; i < layers.size(); ++i) {
            m += layers[i].mass;
            mz += layers[i].mass * (z + 0.5 * layers[i].height);
            z += layers[i].height;
        }
        // the resultant's offset λ·h·(cos, sin) reaches the joint's side or corner
        const double reach = std::max(along / (0.5 * joint_width(layers, j)), across / (0.5 * joint_depth(layers, j)));
        best = std::min(best, 1.0 / (reach * mz / m));
    }
    return best;
}

namespace {

struct PathPoint {
    double lambda = 0.0, top_rotation = 0.0;
};

/// the stack's heights and loads: each layer's bottom (m) and weight (N), the normal force on
/// each bed joint (N), and the size of the joints' moments (N·m) that Newton's tolerance is
/// measured against
struct StackLoads {
    std::vector<double> zb, w, nforce;
    double force_scale = 0.0;
    StackLoads(const std::vector<StackLayer>& l, double g) : zb(l.size() + 1, 0.0), w(l.size()), nforce(l.size(), 0.0) {
        const size_t n = l.size();
        for (size_t i = 0; i < n; ++i) zb[i + 1] = zb[i] + l[i].height, w[i] = l[i].mass * g;
        for (size_t j = n; j-- > 0;) nforce[j] = w[j] + (j + 1 < n ? nforce[j + 1] : 0.0);
        force_scale = nforce[0] * joint_width(l, 0);
    }
};

/// Newton's method on full(x) = 0 from x, with a forward-difference Jacobian (steps of 1e-9 of
/// each unknown's size, at least 1e-9 scale[c]), until the residual is below 1e-10 of
/// `force_scale` (N·m) or a step moves x by less than 1e-13; false when the residual is then
/// (or after 50 iterations) above 1e-6 of it: the path has lost the equilibrium
bool newton(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& full, Eigen::VectorXd& x,
            const Eigen::VectorXd& scale, double force_scale) {
    const long n = x.size();
    for (int it = 0; it < 50; ++it) {
        const Eigen::VectorXd r = full(x);
        if (r.norm() < 1e-10 * force_scale) return true;
        Eigen::MatrixXd jac(n, n);
        for (long c = 0; c < n; ++c) {
            Eigen::VectorXd y = x;
            const double h = 1e-9 * std::max(std::abs(x[c]), scale[c]);
            y[c] += h;
            jac.col(c) = (full(y) - r) / h;
        }
        const Eigen::VectorXd dx = jac.fullPivLu().solve(-r);
        x += dx;
        if (dx.norm() < 1e-13) break;
    }
    return full(x).norm() < 1e-6 * force_scale;
}

/// the rotations (of the top, or the base joint's lean) of the continuation: geometric from a hundredth of the smallest
/// rotation that lifts a joint's edge (θ = 2N/(kn·d·b²): at any kn the first steps find the joints
/// closed, where the path starts from λ = 0) to 0.3 rad, 3000 of them
std::vector<double> base_rotations(const std::vector<StackLayer>& l, const std::vector<double>& nforce, double kn) {
    double lift = INFINITY;
    for (size_t j = 0; j < l.size(); ++j) {
        const double b = std::min(joint_width(l, j), joint_depth(l, j));
        lift = std::min(lift, 2.0 * nforce[j] / (kn * std::max(joint_width(l, j), joint_depth(l, j)) * b * b));
    }
    const double first = std::min(0.01 * lift, 1e-4), last = BlockStack::kWinklerPathEnd;
    const int steps = 3000;
    std::vector<double> r;
    for (int s = 0; s < steps; ++s) r.push_back(first * std::pow(last / first, double(s) / (steps - 1)));
    return r;
}

/// continuation along the quasi-static path: the top's rotation given, (λ, φ1 … φn−1) solved;
/// empty when a step does not converge
std::vector<PathPoint> winkler_path(const std::vector<StackLayer>& l, double g, double kn) {
    const size_t n = l.size();
    const StackLoads loads(l, g);
    const std::vector<double>&zb = loads.zb, &w = loads.w, &nforce = loads.nforce;
    const double force_scale = loads.force_scale;
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
    // unknowns x = (λ, φ1 … φn−1) for a given rotation of the top, φ0 = top − φ1 − … − φn−1: the
    // top turns on whichever joint opens (a base joint's rotation turns back where an upper joint
    // is the mechanism, and a path run in it is lost there)
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    for (const double top : base_rotations(l, nforce, kn)) {
        auto full = [&](const Eigen::VectorXd& y) {
            Eigen::VectorXd phi(n);
            phi[0] = top;
            for (size_t k = 1; k < n; ++k) phi[k] = y[k], phi[0] -= y[k];
            return residual(phi, y[0]);
        };
        Eigen::VectorXd scale = Eigen::VectorXd::Constant(long(n), top);   // the joints' rotations
        scale[0] = 1.0;                                                     // λ
        if (!newton(full, x, scale, force_scale)) return {};
        path.push_back({x[0], top});
    }
    return path;
}

/// the same path for a push at `angle` (rad) to the layers' width axis: every joint leans by a
/// vector φj (its closure grows by φj·r); given the base joint's lean |φ0|, the unknowns are
/// (λ, the direction of φ0, φ1 … φn−1) and each joint's two moment balances the equations
std::vector<PathPoint> winkler_path_oblique(const std::vector<StackLayer>& l, double g, double kn, double angle) {
    using V2 = Eigen::Vector2d;
    const size_t n = l.size();
    const V2 push(std::cos(angle), std::sin(angle));
    const StackLoads loads(l, g);
    const std::vector<double>&zb = loads.zb, &w = loads.w, &nforce = loads.nforce;
    const double force_scale = loads.force_scale;
    auto residual = [&](const std::vector<V2>& phi, double lam) {
        Eigen::VectorXd r(2 * n);
        std::vector<V2> theta(n);   // each layer's lean, the joints' below summed
        V2 acc = V2::Zero();
        for (size_t k = 0; k < n; ++k) theta[k] = acc += phi[k];
        for (size_t j = 0; j < n; ++j) {
            V2 m = V2::Zero();
            for (size_t i = j; i < n; ++i) {
                V2 dx = 0.5 * l[i].height * theta[i];   // centroid i's lean over joint j
                for (size_t k = j; k < i; ++k) dx += l[k].height * theta[k];
                m += w[i] * (lam * (zb[i] + 0.5 * l[i].height - zb[j]) * push + dx);
            }
            r.segment<2>(2 * long(j)) = winkler_joint_moment(phi[j], nforce[j], 0.5 * joint_width(l, j),
                                                            0.5 * joint_depth(l, j), kn) - m;
        }
        return r;
    };
    // x = (λ, ψ, φ1 … φn−1) with φ0 = s·(cos ψ, sin ψ); the closed base joint first leans along
    // I⁻¹·push (I its second moments: a rectangle's grow with the square of its half-sizes)
    Eigen::VectorXd x = Eigen::VectorXd::Zero(long(2 * n));
    const double a0 = joint_width(l, 0), c0 = joint_depth(l, 0);
    x[1] = std::atan2(push.y() / (c0 * c0), push.x() / (a0 * a0));
    std::vector<PathPoint> path;
    for (const double phi0 : base_rotations(l, nforce, kn)) {
        auto full = [&](const Eigen::VectorXd& y) {
            std::vector<V2> phi(n);
            phi[0] = phi0 * V2(std::cos(y[1]), std::sin(y[1]));
            for (size_t k = 1; k < n; ++k) phi[k] = y.segment<2>(2 * long(k));
            return residual(phi, y[0]);
        };
        Eigen::VectorXd scale = Eigen::VectorXd::Constant(long(2 * n), phi0);   // the joints' leans
        scale[0] = scale[1] = 1.0;   // λ and the base lean's direction (rad)
        if (!newton(full, x, scale, force_scale)) return {};
        V2 top = phi0 * V2(std::cos(x[1]), std::sin(x[1]));
        for (size_t k = 1; k < n; ++k) top += x.segment<2>(2 * long(k));
        path.push_back({x[0], top.norm()});
    }
    return path;
}

/// a push along one of the layers' axes takes the one-direction path (swapping the axes for the
/// second); any other angle the two-direction one
std::vector<PathPoint> stack_path(const BlockStack& stack, double kn) {
    const double c = std::cos(stack.push_angle), s = std::sin(stack.push_angle);
    if (std::abs(s) < 1e-12) return winkler_path(stack.layers, stack.g, kn);
    if (std::abs(c) < 1e-12) {
        std::vector<StackLayer> turned = stack.layers;
        for (auto& t : turned) std::swap(t.width, t.depth);
        return winkler_path(turned, stack.g, kn);
    }
    return winkler_path_oblique(stack.layers, stack.g, kn, stack.push_angle);
}

/// the highest point of the path; NaN in both if the path failed or rises to its end (no peak)
PathPoint path_peak(const std::vector<PathPoint>& path) {
    size_t best = 0;
    for (size_t i = 1; i < path.size(); ++i)
        if (path[i].lambda > path[best].lambda) best = i;
    if (path.empty() || best + 1 == path.size()) return {NAN, NAN};
    return path[best];
}

/// the peak of the stack's path, NaN where it would pass the rigid multiplier (which no joint of
/// finite stiffness reaches: a path lost to round-off at extreme kn)
PathPoint stack_peak(const BlockStack& stack, double kn) {
    const PathPoint p = path_peak(stack_path(stack, kn));
    return p.lambda <= stack.rigid_multiplier() ? p : PathPoint{NAN, NAN};
}

}  // namespace

double BlockStack::winkler_multiplier(double kn) const { return stack_peak(*this, kn).lambda; }

double BlockStack::winkler_peak_rotation(double kn) const { return stack_peak(*this, kn).top_rotation; }

namespace {

/// the stack as one rigid body rocking about its base joint's leading edge: mass (kg), the height
/// of its centre of mass (m), its half-width b (m, the centre's distance from the edge along the
/// push) and its inertia about that edge (kg·m²)
struct Monolith {
    double m = 0.0, h = 0.0, b = 0.0, i = 0.0;
};

/// the layers above bed joint j as one body about that joint's leading edge (pushed along the
/// layers' width)
Monolith monolith_of(const std::vector<StackLayer>& layers, size_t j) {
    Monolith r;
    double mz = 0.0, z = 0.0;
    for (size_t k = j; k < layers.size(); ++k) {
        r.m += layers[k].mass;
        mz += layers[k].mass * (z + 0.5 * layers[k].height);
        z += layers[k].height;
    }
    r.h = mz / r.m, r.b = 0.5 * joint_width(layers, j);
    z = 0.0;
    for (size_t k = j; k < layers.size(); ++k) {   // own inertia + m·distance² to the edge
        const StackLayer& l = layers[k];
        const double zc = z + 0.5 * l.height;
        r.i += l.mass * (l.width * l.width + l.height * l.height) / 12.0 + l.mass * (r.b * r.b + zc * zc);
        z += l.height;
    }
    return r;
}

/// the bed joint of the least rigid multiplier along the width (the first of equals): the
/// mechanism the stack turns by
size_t critical_joint(const std::vector<StackLayer>& layers) {
    size_t best = 0;
    double least = INFINITY;
    for (size_t j = 0; j < layers.size(); ++j) {
        const Monolith m = monolith_of(layers, j);
        if (m.b / m.h < least * (1 - 1e-12)) least = m.b / m.h, best = j;
    }
    return best;
}

/// RK4 at 1e-4 s of θ̈ = acc(t, θ) from (θ0, 0) at t = 0: the time (s) at which θ reaches
/// `rotation`, NaN if not within `until`; `rests` holds θ at 0 while acc ≤ 0 there (a rigid
/// block on its base)
double time_to_rotation(const std::function<double(double, double)>& acc, double theta0, bool rests, double rotation,
                        double until) {
    const double dt = 1e-4;
    double t = 0.0, th = theta0, w = 0.0;
    while (t < until) {
        const double k1a = w, k1w = acc(t, th);
        const double k2a = w + 0.5 * dt * k1w, k2w = acc(t + 0.5 * dt, th + 0.5 * dt * k1a);
        const double k3a = w + 0.5 * dt * k2w, k3w = acc(t + 0.5 * dt, th + 0.5 * dt * k2a);
        const double k4a = w + dt * k3w, k4w = acc(t + dt, th + dt * k3a);
        const double th_new = th + dt / 6.0 * (k1a + 2 * k2a + 2 * k3a + k4a);
        w += dt / 6.0 * (k1w + 2 * k2w + 2 * k3w + k4w);
        if (rests && th_new <= 0.0) th = 0.0, w = std::max(0.0, w);   // resting on the base
        else th = th_new;
        t += dt;
        if (!std::isfinite(th)) return NAN;
        if (th >= rotation) return t;
    }
    return NAN;
}

}  // namespace

double BlockStack::rigid_ramp_time(const std::function<double(double)>& lambda, double rotation, double until) const {
    // the layers above the critical joint about its edge (the whole stack where it is the base):
    // θ̈ = (m g/i)[λ(t)(h cos θ + b sin θ) − (b cos θ − h sin θ)], held at θ = 0 while that is < 0:
    // the push acts at the centre's height above the edge, h cos θ + b sin θ, the weight at its
    // distance behind it, b cos θ − h sin θ
    const Monolith s = monolith_of(layers, critical_joint(layers));
    auto acc = [&](double t, double a) {
        const double torque =
            s.m * g * (lambda(t) * (s.h * std::cos(a) + s.b * std::sin(a)) - (s.b * std::cos(a) - s.h * std::sin(a)));
        return (a <= 0.0 && torque <= 0.0) ? 0.0 : torque / s.i;
    };
    return time_to_rotation(acc, 0.0, true, rotation, until);
}

double BlockStack::winkler_ramp_time(double kn, const std::function<double(double)>& lambda, double rotation,
                                     double until) const {
    const std::vector<PathPoint> path = stack_path(*this, kn);
    if (path.size() < 2 || !(path.back().top_rotation > rotation)) return NAN;
    for (size_t k = 1; k < path.size(); ++k)
        if (!(path[k].top_rotation > path[k - 1].top_rotation)) return NAN;   // not one coordinate
    // λ_w(θ): the path's multiplier at top rotation θ, linear between its points, odd in θ
    // (from 0 to the first point the joints are closed: linear)
    auto static_multiplier = [&](double th) {
        const double a = std::abs(th), sign = th < 0 ? -1.0 : 1.0;
        if (a <= path.front().top_rotation) return sign * path.front().lambda * a / path.front().top_rotation;
        const auto hi = std::lower_bound(path.begin(), path.end(), a,
                                         [](const PathPoint& p, double v) { return p.top_rotation < v; });
        const auto lo = hi - 1;
        const double f = (a - lo->top_rotation) / (hi->top_rotation - lo->top_rotation);
        return sign * (lo->lambda + f * (hi->lambda - lo->lambda));
    };
    // the rigid monolith's equation, θ̈ = (m g/i)(h cos θ + b sin θ)(λ(t) − λ_s(θ)), with the
    // Winkler stack's quasi-static multiplier λ_w in place of the rigid λ_s; from its static state
    // under λ(0) on the rising branch
    const Monolith s = monolith_of(layers, critical_joint(layers));
    const PathPoint peak = path_peak(path);
    const double lambda0 = lambda(0.0);
    if (std::isnan(peak.lambda) || std::abs(lambda0) >= peak.lambda) return NAN;
    double lo = 0.0, hi = peak.top_rotation;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (static_multiplier(mid) < std::abs(lambda0) ? lo : hi) = mid;
    }
    const double theta0 = lambda0 < 0 ? -lo : lo;
    auto acc = [&](double t, double a) {
        return s.m * g / s.i * (s.h * std::cos(a) + s.b * std::sin(a)) * (lambda(t) - static_multiplier(a));
    };
    return time_to_rotation(acc, theta0, false, rotation, until);
}

}  // namespace cairn::oracle
