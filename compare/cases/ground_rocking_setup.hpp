#pragma once
/// What the ground_rocking kind's oracles need of a scene, read once and checked, and the two
/// oracles run on it: Housner's equation and the rigid block on dem's Winkler base, both under the
/// scene's own drive (compare/cases/ground_rocking.cpp judges with them).

#include <functional>
#include <string>
#include <vector>

#include "analytic/rocking_oracle.hpp"
#include "analytic/winkler_frame.hpp"
#include "cases/case_analysis.hpp"

namespace cairn::cases {

/// what the oracles need of the scene
struct GroundSetup {
    int free = 0;                        ///< the block among the free blocks (Sample::blocks)
    Vec3 dir = Vec3::UnitX();            ///< unit, world, horizontal: the drive's first push; θ > 0 moves the centre this way
    Vec3 axis = Vec3::UnitY();           ///< z × dir, world: θ is a turn about it
    Vec3 axis_block = Vec3::UnitY();     ///< the same in the block frame, along a block axis
    std::function<Vec3(double)> drive;   ///< the block's loads per unit mass at t (m/s², world); reads the scene, which must outlive it
    std::vector<double> breaks;          ///< s, ascending: where the drive kinks or jumps
    double end = 0.0;                    ///< s: the drive is zero from here on
    double alpha = 0.0;                  ///< slenderness atan(b/h) across the axis, rad
    double scale = 1.0;                  ///< the oracles' horizontal drive is the scene's times this
    double friction_demand = 0.0;        ///< largest |horizontal drive| / (g − its vertical part)
    /// a frame: N ≥ 2 equal columns (the block among them) under one beam that translates as they
    /// rock together (Makris & Vassiliou 2013); N = 1: the block alone
    int columns = 1;
    std::string beam;                    ///< the beam's name (frame)
    double gamma = 0.0;                  ///< m_beam / (N m_column) (frame)
    double p2_factor = 1.0;              ///< p̂²/p² = (1 + 2γ)/(1 + 3γ): the frame rocks as its column, slower
    double ratio = -1.0;                 ///< the frame's impact ratio (1 − 1.5 sin²α + 3γ cos 2α)/(1 + 3γ); < 0: Housner's
    /// m: each column's centre along dir from the block's, the block's (0) first (frame)
    std::vector<double> column_x;
    double beam_x = 0.0;                 ///< m: the beam's centre along dir from the block's (frame)
    double beam_length = 0.0, beam_height = 0.0, beam_depth = 0.0;   ///< m: along dir, up, along the axis (frame)
    double beam_mass = 0.0;              ///< kg (frame)
    /// a stack: every free block, each resting on the one below, the block among them (scene block
    /// indices, bottom first); empty: none
    std::vector<int> stack;
};

/// the scene as the oracles see it; throws cairn::Error naming the key of what they cannot model
GroundSetup read_ground_setup(const Scene& scene);

/// the drive as Housner's oracle takes it: the ground's acceleration along dir and upwards
oracle::BaseMotion ground_base_motion(const GroundSetup& s);

/// Housner's equation of the block, or of the frame (its column with p² times p2_factor: the
/// block under gravity and drive both times p2_factor is that equation exactly)
oracle::RockingOracle ground_oracle(const Scene& scene, const GroundSetup& s);

/// p of the block, or p̂ of the frame, 1/s
double ground_p(const Scene& scene, const GroundSetup& s);

/// the impact ratio of the block (Housner's 1 − 1.5 sin²α) or of the frame
double ground_ratio(const Scene& scene, const GroundSetup& s);

/// Housner's block (or frame) under the scene's drive at the times t, with impact ratio r (< 0: its own)
oracle::RockingResult ground_housner(const Scene& scene, const GroundSetup& s, const std::vector<double>& t, double r);

/// a stack as one rigid block: the bottom block's half-width along the drive and the height of the
/// stack's centre of mass above the base, m
struct StackMonolith {
    double b = 0.0, h = 0.0;
};
StackMonolith stack_monolith(const Scene& scene, const GroundSetup& s);

/// Housner's equation of a stack rocking as one rigid rectangle of its monolith's b and h (exact for
/// a column of equal blocks; a guide, not an oracle, for blocks rocking on one another), θ at the times t
oracle::RockingResult stack_housner(const Scene& scene, const GroundSetup& s, const std::vector<double>& t);


/// the stack's blocks on Winkler bed joints as dem's contact cuts their faces (no drive yet)
oracle::WinklerStack winkler_stack(const Scene& scene, ContactKind contact, const GroundSetup& s);

/// the Winkler block of dem's contact (for a frame, its columns and beam on Winkler joints) under
/// the same drive, θ at the times t
std::vector<double> ground_winkler(const Scene& scene, ContactKind contact, const GroundSetup& s, const std::vector<double>& t);

}  // namespace cairn::cases
