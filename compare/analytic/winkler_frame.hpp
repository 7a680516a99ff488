#pragma once
/// Rigid rectangles rocking in plane on no-tension Winkler joints: a frame of equal columns under
/// one beam (Makris & Vassiliou's trilithon), or a stack of blocks one on another (a column of
/// drums): the references for those on dem's overlap contact. Every column stands on a Winkler base (the top z = 0 of the ground, which moves
/// with the drive); the beam rests on the columns' tops, each top a bed of springs kn per unit area
/// under the beam's bottom face. Each joint acts as WinklerRocking's base does
/// (analytic/winkler_rocking.hpp):
/// over a contact cell d is affine, so the normal force, its centre and the stored energy are closed
/// form; one elastic-then-Coulomb shear spring ks·A per cell, kept at constant energy as A changes;
/// dashpots by dem's contact damping ratio. Every body has 3 degrees of freedom (x, z, θ), all
/// integrated together by RK4 at a fixed fraction of the stiffest contact period, independently of
/// any engine. SI units.

#include <array>
#include <functional>
#include <vector>

#include "analytic/winkler_rocking.hpp"

namespace cairn::oracle {

/// columns of width w (along x, the drive), height h and depth L (along the rocking axis y) standing
/// on the ground z = 0 at centres x_i, and a beam of length, height and depth (bx, bh, bL) whose
/// bottom rests on their tops with its centre at beam_x; θ > 0 lifts a column's −x side
struct WinklerFrame {
    double width, height, depth;        ///< a column's, m
    double mass;                        ///< a column's, kg
    std::vector<double> column_x;       ///< the columns' centres along x, m (the first is the one traced)
    double beam_length, beam_height, beam_depth;   ///< m
    double beam_mass;                   ///< kg
    double beam_x = 0.0;                ///< the beam's centre along x, m
    double g;                           ///< m/s²
    double kn;                          ///< normal stiffness per unit area, N/m³
    double ks = 0.0;                    ///< shear stiffness per unit area, N/m³ (0: no shear springs)
    double mu = 0.0;                    ///< Coulomb coefficient of the shear springs
    /// contact damping ratio ζ, as dem's: a cell's dashpot is c·A_c·ḋ with c = 2ζ√(kn·m/A_face)
    /// (m the pair's reduced mass, a column's on the ground; A_face the hitting face's whole area: a
    /// column's, the beam's bottom being the larger, dem's target); shear 2ζ√(ks·m/A_face)
    double zeta = 0.0;
    static constexpr int max_cells = 256;   ///< bound on all the joints' cells together
    int cells_across = 1;               ///< cells of a column's bottom and top faces across the axis
    int cells_up = 1;                   ///< cells of each side face of a column up its height
    double steps_per_period = 400.0;    ///< RK4 steps per period of the stiffest contact mode
    /// body force per unit mass on every body, {x, z} (m/s²) at time t (s): a ground motion's −a_g
    std::function<std::array<double, 2>(double)> drive{};

    /// from rest, each joint settled by the weight it carries, under `drive` for `duration` (s),
    /// sampling every `sample_dt` (s): the first column's rotation θ and centre, crossings,
    /// amplitudes and the energy ledger as WinklerRocking's. Throws cairn::Error for bad input or
    /// beyond 1e8 steps.
    WinklerTrace rest(double duration, double sample_dt) const;
};

/// one block of a stack, centred on the stack's vertical axis
struct WinklerLayer {
    double width, height, depth;   ///< along x (the drive), up, along the axis y, m
    double mass;                   ///< kg
    int cells_across = 1;          ///< cells of its bottom and top faces across the axis
    int cells_up = 1;              ///< cells of each side face up its height
};

/// blocks stacked on the ground z = 0, each resting on the one below, centred on one vertical
/// axis; each bed joint is the smaller face pressed into the larger (dem's target, the lower one
/// where they are equal), with the hitting block's sides; law and drive as WinklerFrame's
struct WinklerStack {
    std::vector<WinklerLayer> layers;   ///< bottom first
    int traced = 0;                     ///< the layer whose θ and centre the trace records
    double g;                           ///< m/s²
    double kn;                          ///< N/m³
    double ks = 0.0;                    ///< N/m³
    double mu = 0.0;
    double zeta = 0.0;                  ///< as WinklerFrame's, per joint over its pair's reduced mass
    static constexpr int max_cells = 256;   ///< bound on all the layers' cells together (the oracle's cost)
    double steps_per_period = 400.0;
    std::function<std::array<double, 2>(double)> drive{};   ///< body force per unit mass, {x, z}, m/s²

    /// from rest, each joint settled by the weight above it, under `drive` for `duration` (s); as
    /// WinklerFrame::rest
    WinklerTrace rest(double duration, double sample_dt) const;
};

}  // namespace cairn::oracle
