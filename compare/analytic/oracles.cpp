#include "oracles.hpp"

#include <algorithm>
#include <cmath>

namespace cairn::oracle {

double RestingBlock::omega() const { return std::sqrt(stiffness / mass); }
double RestingBlock::period() const { return 2.0 * M_PI / omega(); }

double DroppedBlock::impact_speed() const { return std::sqrt(2.0 * g * gap); }
double DroppedBlock::first_contact() const { return std::sqrt(2.0 * gap / g); }
double DroppedBlock::contact_time() const {
    double w = std::sqrt(stiffness / mass);
    return (M_PI + 2.0 * std::atan(g / (w * impact_speed()))) / w;
}
double DroppedBlock::max_penetration() const {
    double mg = mass * g;
    return (mg + std::sqrt(mg * mg + 2.0 * stiffness * mg * gap)) / stiffness;
}
double DroppedBlock::bounce_period() const { return 2.0 * impact_speed() / g + contact_time(); }

double pulled_block_acceleration(double mass, double g, double pull, double mu) {
    return std::max(0.0, pull / mass - mu * g);
}

double incline_acceleration(double g, double theta, double mu) {
    return std::max(0.0, g * (std::sin(theta) - mu * std::cos(theta)));
}

double launched_on_incline(double g, double theta, double mu, double v0, double t) {
    const double down = g * (std::sin(theta) - mu * std::cos(theta));   // sliding downhill, + downhill
    const double up = g * (std::sin(theta) + mu * std::cos(theta));     // sliding uphill, + downhill
    double s = 0.0;
    if (v0 < 0.0) {   // climbing: braked until it stops at -v0/up
        const double stop = -v0 / up;
        if (t <= stop) return v0 * t + 0.5 * up * t * t;
        s = -v0 * v0 / (2.0 * up);
        t -= stop;
        v0 = 0.0;
    }
    if (down <= 0.0) {   // friction holds it: braked to rest, then held
        if (v0 <= 0.0) return s;
        const double stop = v0 / -down;
        return t <= stop ? s + v0 * t + 0.5 * down * t * t : s + v0 * v0 / (-2.0 * down);
    }
    return s + v0 * t + 0.5 * down * t * t;
}

double HousnerBlock::alpha() const { return std::atan(b / h); }
double HousnerBlock::radius() const { return std::sqrt(b * b + h * h); }
double HousnerBlock::p() const { return std::sqrt(3.0 * g / (4.0 * radius())); }

double HousnerBlock::first_impact(double theta0) const {
    // t1 = ∫0^θ0 dθ / √(2p²[cos(α−θ0) − cos(α−θ)]) (energy from rest at θ0); substitute θ = θ0 − θ0·s² to remove the
    // inverse-square-root singularity at θ0, then Gauss-Legendre on s ∈ [0, 1]
    const double a = alpha(), p2 = p() * p();
    auto integrand = [&](double s) {
        double th = theta0 * (1.0 - s * s);
        double den = 2.0 * p2 * (std::cos(a - theta0) - std::cos(a - th));
        return den > 0.0 ? 2.0 * theta0 * s / std::sqrt(den) : 0.0;
    };
    // composite 8-point Gauss over 64 panels: smooth integrand after the substitution
    static const double x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                0.7966664774136267,  0.9602898564975363};
    static const double w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                0.2223810344533745, 0.1012285362903763};
    const int panels = 64;
    double sum = 0.0;
    for (int k = 0; k < panels; ++k) {
        double lo = double(k) / panels, hi = double(k + 1) / panels;
        for (int i = 0; i < 8; ++i) sum += 0.5 * (hi - lo) * w[i] * integrand(0.5 * (lo + hi) + 0.5 * (hi - lo) * x[i]);
    }
    return sum;
}

double HousnerBlock::first_impact_linear(double theta0) const {
    return std::acosh(1.0 / (1.0 - theta0 / alpha())) / p();
}

double HousnerBlock::impact_omega(double theta0) const {
    const double a = alpha();
    return std::sqrt(2.0 * p() * p() * (std::cos(a - theta0) - std::cos(a)));
}

double HousnerBlock::velocity_ratio() const {
    double s = std::sin(alpha());
    return 1.0 - 1.5 * s * s;
}

double HousnerBlock::amplitude_after(double theta0, int n) const {
    const double a = alpha(), r = std::pow(velocity_ratio(), 2 * n);
    double c = std::cos(a) + r * (std::cos(a - theta0) - std::cos(a));
    return a - std::acos(std::min(1.0, c));
}

}  // namespace cairn::oracle

namespace cairn::oracle {

double dashpot_for_ratio(double zeta, double stiffness, double mass) {
    return 2.0 * zeta * std::sqrt(stiffness * mass);
}

namespace {

/// one RK4 step of ẍ = f(x, ẋ)
template <class F>
void rk4(double& x, double& v, double h, const F& f) {
    double k1x = v, k1v = f(x, v);
    double k2x = v + 0.5 * h * k1v, k2v = f(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    double k3x = v + 0.5 * h * k2v, k3v = f(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    double k4x = v + h * k3v, k4v = f(x + h * k3x, v + h * k3v);
    x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
}

}  // namespace

DampedDrop::Bounce DampedDrop::first_bounce() const {
    // x: height of the bottom above the plane; inside the contact the force never pulls
    auto acc = [&](double x, double v) {
        double f = x < 0.0 ? std::max(0.0, -stiffness * x - damping * v) : 0.0;
        return f / mass - g;
    };
    const double v0 = std::sqrt(2.0 * g * gap);
    const double h = 2.0 * M_PI * std::sqrt(mass / stiffness) / 2e5;
    Bounce b;
    double x = 0.0, v = -v0, t = 0.0;
    for (long i = 0; i < 100000000L; ++i) {
        double xp = x, vp = v;
        rk4(x, v, h, acc);
        t += h;
        b.max_penetration = std::max(b.max_penetration, -x);
        if (x >= 0.0 && v > 0.0) {
            // back at the plane: interpolate the crossing within the step
            double f = xp / (xp - x);
            b.contact_time = t - h + f * h;
            b.exit_speed = vp + f * (v - vp);
            break;
        }
    }
    b.restitution = v0 > 0.0 ? b.exit_speed / v0 : 0.0;
    return b;
}

double DampedDrop::bounce_period() const {
    Bounce b = first_bounce();
    return b.contact_time + 2.0 * b.exit_speed / g;
}

std::vector<double> DampedDrop::heights(const std::vector<double>& times) const {
    auto acc = [&](double x, double v) {
        double f = x < 0.0 ? std::max(0.0, -stiffness * x - damping * v) : 0.0;
        return f / mass - g;
    };
    const double h = 2.0 * M_PI * std::sqrt(mass / stiffness) / 2e4;
    std::vector<double> out;
    out.reserve(times.size());
    double x = gap, v = 0.0, t = 0.0;
    for (double target : times) {
        while (t + h <= target) {
            rk4(x, v, h, acc);
            t += h;
        }
        double xs = x, vs = v;
        if (target > t) rk4(xs, vs, target - t, acc);
        out.push_back(xs);
    }
    return out;
}

double HousnerBlock::amplitude_after(double theta0, int n, double r) const {
    const double a = alpha(), e = std::pow(r, 2 * n);
    double c = std::cos(a) + e * (std::cos(a - theta0) - std::cos(a));
    return a - std::acos(std::min(1.0, c));
}

std::vector<double> HousnerBlock::angles(double theta0, double r, const std::vector<double>& times) const {
    const double a = alpha(), p2 = p() * p();
    auto acc = [&](double th, double) { return -p2 * std::sin(a * (th >= 0.0 ? 1.0 : -1.0) - th); };
    const double h = 1e-5;
    std::vector<double> out;
    out.reserve(times.size());
    double th = theta0, w = 0.0, t = 0.0;
    auto advance = [&](double& x, double& v, double step) {
        double xp = x;
        rk4(x, v, step, acc);
        // an impact when θ changes sign: velocity ratio r (the small overshoot is kept)
        if ((xp > 0.0 && x <= 0.0) || (xp < 0.0 && x >= 0.0)) v *= r;
    };
    for (double target : times) {
        while (t + h <= target) {
            advance(th, w, h);
            t += h;
        }
        double xs = th, vs = w;
        if (target > t) advance(xs, vs, target - t);
        out.push_back(xs);
    }
    return out;
}

}  // namespace cairn::oracle
