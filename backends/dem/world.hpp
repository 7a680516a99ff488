#pragma once
/// The in-house engine's world: blocks (rigid or deformable), contacts, loads, and the explicit
/// central-difference step as named stages.

#include <string>
#include <vector>

#include "backend/settle.hpp"
#include "block.hpp"
#include "block_builder.hpp"
#include "contact.hpp"
#include "backend/backend.hpp"
#include "scene/scene.hpp"

namespace cairn::dem {

/// Energy accounts of the world, J.
struct EnergyAccounts {
    double contact = 0.0;       ///< stored in contact springs now
    double strain = 0.0;        ///< stored in deformable blocks now
    double dissipated = 0.0;    ///< slip, dashpots, mass and stiffness damping so far
    double external = 0.0;      ///< work of the loads so far
};

/// What the settling before t = 0 did (World::settle).
struct SettleReport {
    bool settled = false;     ///< the blocks came to rest and start from there; false: started as given
    long steps = 0;           ///< steps taken while settling
    double residual = 0.0;    ///< the largest unbalanced force at the end, a fraction of the block's weight
    double largest_move = 0.0;///< the largest move of a block's centre while settling, m
    std::string block;        ///< the block that moved most
    std::string why;          ///< settled = false: why (a block moved as a mechanism, or no rest within the cap)
    long slip_steps = 0;      ///< of `steps`, those taken with the friction cap on (the second phase)
    bool slip_refused = false;///< the second phase moved a block (the loads at t = 0 beat friction): phase 1 kept
};

class World {
public:
    /// build the blocks of a validated scene, with a broad-phase margin (m)
    World(const Scene& scene, double margin);
    /// set the time step (s) and evaluate the forces at t = 0; call once before step()
    void start(double dt);
    /// bring the free blocks to rest under gravity and the loads acting at t = 0 before t = 0 at the
    /// time step dt (s): from rest, gravity and those loads ramp from 0 and the blocks relax by
    /// kinetic damping (all stopped past each peak of the kinetic energy) in rounds of a fixed
    /// count of steps, first with no shear spring slipping, then (at most settle::kSlipRounds
    /// rounds) with the friction cap on; a phase is done once the largest unbalanced force at the
    /// end of a round is below settle::kResidual of a block's weight (within a cap of steps) and no
    /// block moved by settle::kMove of its shortest edge or turned by settle::kTurn. A second phase
    /// that fails leaves the first's state; a first that fails restores the state as given bit for
    /// bit. Either way the blocks then carry the scene's initial velocities, the energy accounts
    /// start at zero and t = 0. Call before start() (docs/dem.md, "Settled start")
    SettleReport settle(double dt);
    /// advance one step; false if the run can no longer be trusted (see failure())
    bool step();
    /// why the last step failed: an element of a deformable block turned inside out (det F <= 0
    /// at a Gauss point), the state is not finite, or a block sank into another by more than a
    /// quarter of the smaller block's shortest edge
    const std::string& failure() const { return failure_; }
    /// simulated time, s
    double time() const { return t_; }
    const std::vector<Block>& blocks() const { return blocks_; }
    const EnergyAccounts& energy() const { return energy_; }
    /// kinetic energy of the step, J: ½ v⁻ᵀ·M·(2v − v⁻) with v⁻ the velocity before the
    /// end-of-step half kick, i.e. ½vᵀMv less the kinetic energy of that half kick's velocity
    /// change, (dt²/8)·FᵀM⁻¹F: the kinetic part of the energy the central-difference step keeps
    /// exactly under linear forces (docs/dem.md, Energy)
    double kinetic() const;
    /// gravitational potential energy (zero at the origin), J
    double potential() const;
    /// world position of probe i of the scene, m
    Vec3 probe(int i) const { return world_position(blocks_[probes_[i].block], probes_[i]); }
    /// active contact points after the last force evaluation
    int active_contacts() const { return active_; }
    /// keep per-point contact forces for contact_points(); call before start()
    void record_contacts(bool on) { contacts_.keep_forces(on); }
    /// overlap scheme: leave out the faces that cannot reach their target before the next refresh,
    /// bringing a block's back before it turns by kRefreshTurn (default on; off: every face whose
    /// box meets the target's, refreshed on motion alone), candidates rebuilt; call before start()
    void prune_contacts(bool on) {
        prune_ = on;
        contacts_.prune(on);
        contacts_.refresh(blocks_);
    }
    /// candidate hitting faces now (those of the last refresh, and any widen brought back)
    size_t candidate_count() const { return contacts_.candidates().size(); }
    /// penetrating hitting points of the last force evaluation with their forces (empty unless
    /// record_contacts(true)); block_a is the hitting block, the normal that of the target face
    std::vector<ContactPoint> contact_points() const;
    /// contact refreshes forced early because a block moved (or was about to move) more than half
    /// the margin; where a block moves more than half the margin in one step, the refresh grows the
    /// margin to four steps' move of the fastest block, so that no contact is missed
    int early_refreshes() const { return early_refreshes_; }
    /// element updates done so far (deformable blocks)
    long long element_updates() const { return element_updates_; }

private:
    void refresh_if_due();
    /// end: the end-of-step half kick, which adds the contact events' corrections
    void kick(double h, bool end);
    void drift();
    void compute_forces();
    void add_events();
    bool state_finite() const;
    std::string inversion_message(size_t block) const;

    /// one phase of settle(): steps first … last of the plan; true once at rest
    bool relax(const settle::Schedule& plan, long first, long last, const std::vector<Block>& given, SettleReport& rep);
    /// settle(): every free block at rest (kinetic damping)
    void stop_blocks();
    /// largest unbalanced force (rigid: also torque over r_max) of a free block, over its weight
    double unbalanced() const;
    /// ½vᵀMv of the free blocks, J
    double motion_energy() const;

    const Scene& scene_;
    bool settling_ = false;      // settle(): gravity and the loads at t = 0 scaled
    double gravity_scale_ = 1.0; // settle(): the ramp of gravity
    double margin_ = 0.0;   // the scene's broad-phase margin, m
    double dt_ = 0.0;
    double t_ = 0.0;
    int steps_since_refresh_ = 0;
    int early_refreshes_ = 0;
    bool prune_ = true;
    long long element_updates_ = 0;
    std::vector<Block> blocks_;
    ContactSet contacts_;
    EnergyAccounts energy_;
    int active_ = 0;
    std::string failure_;
    std::string inversion_;   // the first element inversion seen, kept until step() reports it
    ContactTotals last_contact_;
    std::vector<Vec3> force_, torque_;          // rigid blocks: resultant of the current step
    std::vector<double> loss_;                  // per block: mass-damping loss of the last kick, J
    std::vector<char> turned_;                  // per block: about to turn past kRefreshTurn (refresh_if_due)
    std::vector<std::vector<Vec3>> accel_;      // deformable blocks: nodal accelerations
    // contact events (a point entering or leaving inside the step): the end-of-step half kick's
    // forces of the blocks they touch
    std::vector<char> event_;                   // per block: has events this step
    std::vector<Vec3> force_end_, torque_end_;  // rigid blocks
    std::vector<std::vector<Vec3>> accel_end_;  // deformable blocks
    std::vector<std::vector<Vec3>> f_end_;      // deformable blocks: node forces with the events
    std::vector<MaterialPoint> probes_, loads_;
    std::vector<Vec3> load_point_, load_force_; // per load: last application point and force
};

}  // namespace cairn::dem
