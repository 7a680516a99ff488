#include "study/impact_measure.hpp"

#include <cmath>

#include "cases/case_util.hpp"
#include "metrics/signal.hpp"

namespace cairn::study {

namespace {

/// the angular-velocity component about `axis` of free block f
metrics::Series omega_series(const std::vector<Sample>& s, int f, const Vec3& axis) {
    metrics::Series w;
    for (const auto& x : s) {
        w.t.push_back(x.t);
        w.y.push_back(x.blocks[size_t(f)].angular_velocity.dot(axis));
    }
    return w;
}

/// value at t of the least-squares parabola through the samples in [t0, t1]; NaN if under 3 samples
double fit_at(const metrics::Series& w, double t0, double t1, double t) {
    int count = 0;
    for (double x : w.t) count += x >= t0 && x <= t1;
    if (count < 3) return NAN;
    const auto c = metrics::polyfit(w, 2, t0, t1);
    return c[0] + c[1] * t + c[2] * t * t;
}

}  // namespace

RockingImpact first_rocking_impact(const std::vector<Sample>& s, int f, const Vec3& axis, double settle,
                                   double window) {
    RockingImpact r;
    const auto th = cases::angle_series(s, f, axis);
    const auto cross = metrics::crossings(th, 0.0, metrics::Crossing::any);
    if (cross.empty()) return r;
    r.found = true;
    r.time = cross[0];
    const auto w = omega_series(s, f, axis);
    r.omega_before = fit_at(w, r.time - window, r.time - 1e-12, r.time);
    const double a0 = r.time + settle;
    r.omega_after = w.t.back() >= a0 + window ? fit_at(w, a0, a0 + window, r.time) : NAN;
    r.ratio = r.omega_after / r.omega_before;
    return r;
}

double bounce_period(const std::vector<Sample>& s, int f, double z_contact) {
    const auto z = cases::com_series(s, f, 2, false);
    const auto c = metrics::crossings(z, z_contact, metrics::Crossing::down);
    return c.size() >= 2 ? c[1] - c[0] : NAN;
}

}  // namespace cairn::study
