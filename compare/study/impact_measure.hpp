#pragma once
/// Events of the inertia study read from a run's samples: a rocking block's first impact and its
/// angular-velocity ratio, a dropped block's bounce period.

#include <vector>

#include "backend/backend.hpp"

namespace cairn::study {

/// the first impact of a rocking block (θ back to 0 about the rocking axis)
struct RockingImpact {
    bool found = false;          ///< false: θ never came back to 0 within the run
    double time = 0.0;           ///< first zero crossing of θ, linear between samples, s
    double omega_before = 0.0;   ///< angular velocity about the axis at the crossing, from before, rad/s
    double omega_after = 0.0;    ///< the same just after the impact, extrapolated back to the crossing, rad/s
    double ratio = 0.0;          ///< omega_after / omega_before (NaN when the run ends too soon after)
};

/// First impact of free block `f` rocking about the unit world `axis`. ω before: the slope at the
/// crossing t of the parabola fitted to θ(t) over [t − window, t); ω after: the same over
/// [t + settle, t + settle + window], extrapolated back to t. θ, not ω, is fitted: after an impact on
/// an undamped penalty contact the block hops on its new edge (ω jumps at every touch, θ stays
/// continuous), so the fit gives the mean rotation rate the impact left. `settle` (s) skips the
/// contact's own transient.
RockingImpact first_rocking_impact(const std::vector<Sample>& s, int f, const Vec3& axis, double settle,
                                   double window);

/// Bounce period of a dropped free block f: the time between the first two downward crossings of its
/// centre's height through its height at first contact `z_contact` (m); NaN with fewer than two
double bounce_period(const std::vector<Sample>& s, int f, double z_contact);

}  // namespace cairn::study
