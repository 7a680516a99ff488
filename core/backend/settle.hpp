#pragma once
/// The settled start (run.settle) shared by the penalty-contact backends, dem and MuJoCo matched:
/// blocks placed at rest sink into the static state of their springs under gravity before t = 0
/// (docs/dem.md, "Settled start").

namespace cairn::settle {

/// gravity ramps over this many bounce periods 2π√(m/(kn·A)) of the softest block on its
/// smallest side, then the blocks relax in rounds of kRestPeriods more, the unbalanced force judged
/// only at the end of a round: where the settling stops is a fixed count of steps, not where a
/// threshold was crossed (block order and names change only round-off)
constexpr double kRampPeriods = 5.0;
constexpr double kRestPeriods = 30.0;
/// never more steps than this, nor than the run's own steps if those are more
constexpr long kStepCap = 20000;
/// at rest: no block's unbalanced force (or torque over its r_max) above this fraction of its weight
constexpr double kResidual = 1e-3;
/// not at rest as placed: a block's centre moved by this fraction of its shortest edge, or it
/// turned by this angle (rad), while it settled (a mechanism: it rocks, slides or falls)
constexpr double kMove = 0.02;
constexpr double kTurn = 0.02;

}  // namespace cairn::settle
