#pragma once
/// A rigid rectangular block rocking in plane on a no-tension Winkler foundation: the reference for
/// rocking on the overlap contact (docs/dem.md, "Rocking at the paper's stiffness"). The base is a
/// bed of vertical springs kn per unit area (N/m³) under every part of the block's lower surface
/// that lies below its top (the bottom face, and the side face of a sunken corner), each pressing
/// kn·max(d, 0) with d the depth below the top: over a face d is affine, so the force, its centre
/// and the stored energy are closed form. Shear: one elastic-then-Coulomb spring ks·A per face (or
/// cell) in contact (A its contact area), its offset grown by the tangential velocity at the face's
/// pressure centre and kept at constant energy as A changes; dashpots as dem's contact damping ratio. The
/// block has 3 degrees of freedom (x, z, θ), integrated by RK4 at a fixed fraction of the stiffest
/// contact period, independently of any engine. Each face may be cut into equal cells, each with
/// its own pressure centre, dashpot and shear spring (dem's sub-contacts: the normal force and its
/// moment do not depend on the cut, only the shear does). SI units.

#include <array>
#include <functional>
#include <vector>

namespace cairn::oracle {

/// the rocking history of a block on a Winkler base
struct WinklerTrace {
    std::vector<double> t, theta, x, z;   ///< samples: time (s), rotation about +y (rad), centre (m)
    std::vector<double> crossings;        ///< times θ passes 0, s
    std::vector<double> amplitudes;       ///< largest |θ| between successive crossings (after each), rad
    std::vector<double> touches;          ///< times the lifted bottom edge reaches the base's top (the −x edge first, then alternately), s
    double energy_error = 0.0;            ///< largest |E(t) + dissipated − work − E0| over the run, J
    double dissipated = 0.0;              ///< dashpots, slip and released shear springs at the end, J
    int slip_steps = 0;                   ///< steps on which a shear spring reached μ·Fn and slipped
    double step = 0.0;                    ///< integration step, s
};

/// a rigid block of width w (across the rocking axis, along x), height h and depth L (along the
/// axis, y) on a Winkler base whose top is z = 0; θ > 0 lifts the −x side (a rotation about +y)
struct WinklerRocking {
    double width, height, depth;   ///< m
    double mass;                   ///< kg
    double g;                      ///< m/s²
    double kn;                     ///< normal stiffness per unit area, N/m³
    double ks = 0.0;               ///< shear stiffness per unit area, N/m³ (0: no shear springs, no friction)
    double mu = 0.0;               ///< Coulomb coefficient of the shear springs
    /// contact damping ratio ζ, as dem's: a face's dashpot is c·A_c·ḋ at its pressure centre with
    /// c = 2ζ√(kn·m/A_side) per unit area (A_side the whole face's area, A_c its part in contact);
    /// shear 2ζ√(ks·m/A_side) while sticking; the normal force never pulls
    double zeta = 0.0;
    static constexpr int max_cells = 96;   ///< bound on cells_across + 2·cells_up
    int cells_across = 1;          ///< cells of the bottom face across the axis (dem: divisions × subdivision)
    int cells_up = 1;              ///< cells of each side face up its height
    /// RK4 steps per period 2π/ω of the stiffest contact mode (all lower faces pressed, bounded
    /// from above); 400 keeps the first crossing converged to 1e-7 relative
    double steps_per_period = 400.0;
    /// body force per unit mass on the block, {x, z} (m/s²) at time t (s): a ground motion's −a_g
    /// (the block is solved in the ground's frame); empty: none. Its work is in the energy ledger
    std::function<std::array<double, 2>(double)> drive{};

    /// moment of inertia about the centre, m(w² + h²)/12, kg·m²
    double inertia() const { return mass * (width * width + height * height) / 12.0; }
    /// the static settlement of the block standing on its base, W/(kn·w·L), m
    double settlement() const { return mass * g / (kn * width * depth); }

    /// at rest on its base, settled by W/(kn·w·L), under `drive` for `duration` (s), sampling every
    /// `sample_dt` (s): rock(0, duration, sample_dt, settlement())
    WinklerTrace rest(double duration, double sample_dt) const { return rock(0.0, duration, sample_dt, settlement()); }

    /// release at rest tilted θ0 (rad, 0 ≤ θ0 < atan(w/h)) with its +x bottom edge just touching the
    /// base's top (θ0 = 0: the whole bottom just touching), optionally lowered by `sink` (m); run for
    /// `duration` (s), sampling every `sample_dt` (s). Throws cairn::Error for bad input or beyond 1e8 steps.
    WinklerTrace rock(double theta0, double duration, double sample_dt, double sink = 0.0) const;
};

}  // namespace cairn::oracle
