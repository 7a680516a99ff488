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
