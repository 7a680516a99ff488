#pragma once
/// The in-house engine's world: blocks, contacts, loads and the explicit step as named stages.

#include <string>
#include <vector>

#include "block.hpp"
#include "contact.hpp"
#include "scene/scene.hpp"

namespace cairn::dem {

/// Energy accounts of the world, J.
struct EnergyAccounts {
    double contact = 0.0;       ///< stored in contact springs now
    double dissipated = 0.0;    ///< slip, dashpots and mass damping so far
    double external = 0.0;      ///< work of the loads so far
};

class World {
public:
    /// build from a validated scene with time step dt (s) and broad-phase margin (m)
    World(const Scene& scene, double dt, double margin);
    /// advance one step; false if the state is no longer finite
    bool step();
    /// simulated time, s
    double time() const { return t_; }
    const std::vector<Block>& blocks() const { return blocks_; }
    const EnergyAccounts& energy() const { return energy_; }
    /// kinetic energy, J
    double kinetic() const;
    /// gravitational potential energy (zero at the origin), J
    double potential() const;
    /// active contact points after the last force evaluation
    int active_contacts() const { return active_; }
    /// contact refreshes forced early because a block moved more than half the margin
    int early_refreshes() const { return early_refreshes_; }
    /// the contact set (for inspection)
    const ContactSet& contacts() const { return contacts_; }

private:
    void refresh_if_due();
    void kick(double h);
    void drift();
    void compute_forces();
    bool state_finite() const;

    const Scene& scene_;
    double dt_;
    double t_ = 0.0;
    long long step_ = 0;
    int steps_since_refresh_ = 0;
    int early_refreshes_ = 0;
    std::vector<Block> blocks_;
    ContactSet contacts_;
    EnergyAccounts energy_;
    int active_ = 0;
    std::vector<Vec3> force_, torque_;        // per block: resultant of the current step
    std::vector<Vec3> load_point_, load_force_;// per load: last application point and force
};

/// a block of the engine from its scene definition (rigid model)
Block make_rigid_block(const BlockDef& def, const Material& mat, double grid_spacing);

}  // namespace cairn::dem
