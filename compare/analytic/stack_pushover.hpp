#pragma once
/// A stack of rectangular layers (the drums of a column, the courses of a wall) on a fixed base,
/// pushed by a uniform lateral acceleration λ·g: the multiplier λ at which it overturns.
/// Layers are centred on one vertical axis and share their horizontal axes; each bed joint is as
/// wide as the narrower of the two layers it joins (the first joins the base, taken wider than the
/// first layer). The push acts along the layers' width, or at `push_angle` to it.

#include <functional>
#include <vector>

namespace cairn::oracle {

/// one layer of the stack, bottom first
struct StackLayer {
    double height;   ///< m
    double width;    ///< along the layers' first axis, m: along the push when push_angle = 0
    double depth;    ///< along their second axis, m: across the push when push_angle = 0
    double mass;     ///< kg
};

/// the stack and its overturning multipliers
struct BlockStack {
    std::vector<StackLayer> layers;   ///< bottom to top
    double g = 9.81;                  ///< m/s²
    /// rad: the Winkler path's continuation runs to this rotation (of the top, or the base's lean)
    static constexpr double kWinklerPathEnd = 0.3;
    double push_angle = 0.0;          ///< rad, from the layers' first (width) axis to the push

    /// rigid blocks: the least λ over the mechanisms "all the layers above bed joint j turn as one
    /// body about the joint's leading edge": min over j of (joint half-width)/(height of their
    /// centre of mass above the joint). A column of equal drums: B/H. At an angle the normal
    /// resultant leaves the joint's rectangle through a side or a corner: min over j of
    /// 1/(h_j·max(|cos|/half-width, |sin|/half-depth)).
    double rigid_multiplier() const;
    /// joints of no-tension Winkler springs kn (N/m³, the penalty contact integrated over the
    /// joint): each joint opens gradually (its moment tends to N·B/2 only as its rotation grows)
    /// while the layers above lean over it, so the quasi-static path of λ against rotation has a
    /// peak below the rigid value; returns that peak, found by continuation in the top's
    /// rotation with the other joints in equilibrium (small rotations). At an angle to the layers'
    /// axes each joint leans in two directions (a corner lifts first): the continuation runs in the
    /// size of the base joint's lean, its direction solved with the rest. → rigid_multiplier() as
    /// kn → ∞. NaN if the continuation does not converge or finds no peak.
    double winkler_multiplier(double kn) const;
    /// the rotation of the top layer (rad) at that peak (NaN as above)
    double winkler_peak_rotation(double kn) const;
    /// a monolithic rigid stack (rocking about the base joint's edge, exact nonlinear equation of
    /// motion, RK4 at 1e-4 s) at rest from t = 0 under a lateral acceleration λ(t)·g: the time (s)
    /// at which its rotation reaches `rotation` (rad), or NaN if not within `until` (s). Against a
    /// slow ramp this is the quasi-static multiplier plus the ramp's dynamic lag.
    double rigid_ramp_time(const std::function<double(double)>& lambda, double rotation, double until) const;
    /// the same under the joints of no-tension Winkler springs kn (N/m³): the monolith's equation
    /// with the quasi-static multiplier of winkler_multiplier's path, λ_w(θ) at the top's rotation
    /// θ, in place of the rigid one: i θ̈ = m g (h cos θ + b sin θ)(λ(t) − λ_w(θ)), from its static
    /// state under λ(0). The rising branch is stable (the stack leans with the ramp), past the
    /// peak it runs away: the peak plus the lag. NaN as above, or where the path has no peak or
    /// ends before `rotation`.
    double winkler_ramp_time(double kn, const std::function<double(double)>& lambda, double rotation,
                             double until) const;
};

}  // namespace cairn::oracle
