#pragma once
/// The settled start (run.settle) shared by the penalty-contact backends, dem and MuJoCo matched:
/// blocks placed at rest sink into the static state of their springs under gravity and the loads
/// acting at t = 0 before t = 0
/// (docs/dem.md, "Settled start").

#include <algorithm>
#include <cmath>
#include <string>

namespace cairn::settle {

/// gravity ramps over this many bounce periods 2π√(m/(kn·A)) of the softest block on its
/// smallest side, then the blocks relax in rounds of kRestPeriods more, the unbalanced force judged
/// only at the end of a round: where the settling stops is a fixed count of steps, not where a
/// threshold was crossed (block order and names change only round-off)
constexpr double kRampPeriods = 5.0;
constexpr double kRestPeriods = 30.0;
/// the second phase (friction cap back on) takes at most this many rounds
constexpr long kSlipRounds = 2;
/// never more steps than this, nor than the run's own steps if those are more
constexpr long kStepCap = 20000;
/// at rest: no block's unbalanced force (or torque over its r_max) above this fraction of its weight
constexpr double kResidual = 1e-3;
/// not at rest as placed: a block's centre moved by this fraction of its shortest edge, or it
/// turned by this angle (rad), while it settled (a mechanism: it rocks, slides or falls)
constexpr double kMove = 0.02;
constexpr double kTurn = 0.02;

/// the bounce period 2π√(m/(kn·A)) of a block of mass m (kg) on springs kn (N/m³) over area A (m²), s
inline double bounce_period(double mass, double kn, double area) { return 2.0 * M_PI * std::sqrt(mass / (kn * area)); }

/// The step counts of one settling.
struct Schedule {
    long cap = 1;     ///< at most this many steps
    long ramp = 1;    ///< steps over which gravity ramps from 0 to g
    long round = 1;   ///< steps of a round of relaxation
    /// for the slowest bounce period (s) at the time step dt (s) of a run of `duration` (s)
    Schedule(double period, double dt, double duration) {
        cap = std::max(kStepCap, long(std::min(1e9, std::ceil(duration / dt))));
        ramp = std::clamp(long(std::ceil(kRampPeriods * period / dt)), 1L, cap);
        round = std::max(1L, long(std::ceil(kRestPeriods * period / dt)));
    }
    /// the share of gravity at step k (from 1)
    double gravity(long k) const { return std::min(1.0, double(k) / double(ramp)); }
    /// step k ends a round: the unbalanced force is judged there
    bool judged(long k) const { return k >= ramp && (k - ramp) % round == round - 1; }
};

/// why block `name`, which moved `move` (m) and turned `angle` (rad) while settling, is not at rest
/// as placed (shortest edge `min_edge`, m); empty while it is within kMove and kTurn
inline std::string not_at_rest(const std::string& name, double move, double angle, double min_edge) {
    if (move <= kMove * min_edge && angle <= kTurn) return {};
    return "block " + name + " moved " + std::to_string(move) + " m and turned " + std::to_string(angle) +
           " rad under gravity: not at rest as placed";
}

}  // namespace cairn::settle
