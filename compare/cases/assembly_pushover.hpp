#pragma once
/// A pushover of any assembly of blocks (a wall pushed in its plane, an arch, a stack off its axis
/// or pushed at an angle): the scene's blocks under gravity and its ramped horizontal record, read
/// as a rigid-block limit analysis (compare/analytic/block_limit_analysis.hpp). The collapse
/// multiplier λ bounds from below the a/g at which a block turns past the threshold; its mechanism,
/// as one degree of freedom pushed by the record beyond λ, bounds the ramp's lag from above.

#include <string>

#include "cases/case_analysis.hpp"

namespace cairn::cases {

/// the limit analysis of a pushover scene and its mechanism
struct AssemblyPushover {
    double lambda = 0.0;             ///< collapse multiplier: a/g at which a mechanism forms
    double lambda_inset = 0.0;       ///< the same with every joint hinging 1 mm inside its edges (0: it
                                     ///< cannot stand so)
    double record_sign = 1.0;        ///< +1, or −1 when the record pushes against its direction
    double mass = 0.0;               ///< generalised mass of the mechanism, kg (per its amplitude q, m)
    double push = 0.0;               ///< generalised live force per unit of a/g, N
    double turn = 0.0;               ///< largest block rotation per unit amplitude q, rad/m
    double slip_share = 0.0;         ///< largest joint slip in the mechanism against its largest
                                     ///< contact-point speed: > 0.05, sliding takes part
    bool friction_binds = false;     ///< with 10 % less friction λ falls: the static state leans on it
    int interfaces = 0;              ///< joints found, count
    /// the a/g at which the linearised mechanism, at rest until the record passes λ, has turned a
    /// block by `rotation` (rad); NaN if not within the run. Geometric softening only speeds the
    /// mechanism up, so this bounds the a/g from above
    double lagged_multiplier(const Scene& scene, double rotation) const;
};

/// throws cairn::Error naming the key unless the scene is driven by one horizontal record alone,
/// from rest (what both pushover oracles model)
void require_pushover_drive(const Scene& scene);

/// reads the scene's pushover as a limit analysis; throws cairn::Error naming the key when the
/// scene is not one (no single horizontal record, other loads or initial speeds, no admissible
/// state under gravity, a live load carried without limit)
AssemblyPushover assembly_pushover(const Scene& scene);

/// the metrics of a run against the assembly's limit analysis (the pushover kind's analysis for a
/// scene that is not a centred stack pushed along a side)
CaseAnalysis analyse_assembly_pushover(const Scene& scene, const std::vector<Sample>& s, ContactKind contact,
                                       double threshold);

}  // namespace cairn::cases
