#include "study/impact_measure.hpp"

#include <cmath>

#include "cases/case_util.hpp"
#include "metrics/signal.hpp"

namespace cairn::study {

namespace {

/// slope at t of the least-squares parabola through the samples in [t0, t1]; NaN if under 3 samples
double slope_at(const metrics::Series& th, double t0, double t1, double t) {
    int count = 0;
    for (double x : th.t) count += x >= t0 && x <= t1;
    if (count < 3) return NAN;
    const auto c = metrics::polyfit(th, 2, t0, t1);
    return c[1] + 2.0 * c[2] * t;
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
    r.omega_before = slope_at(th, r.time - window, r.time - 1e-12, r.time);
    const double a0 = r.time + settle;
    r.omega_after = th.t.back() >= a0 + window ? slope_at(th, a0, a0 + window, r.time) : NAN;
    r.ratio = r.omega_after / r.omega_before;
    return r;
}

double bounce_period(const std::vector<Sample>& s, int f, double z_contact) {
    const auto z = cases::com_series(s, f, 2, false);
    const auto c = metrics::crossings(z, z_contact, metrics::Crossing::down);
    return c.size() >= 2 ? c[1] - c[0] : NAN;
}

}  // namespace cairn::study
