#pragma once
/// The one interface every backend implements (in-house DEM, Bullet, ODE, MuJoCo).
/// A backend owns all of its mutable state; the scene it is built from is read-only.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "backend/capabilities.hpp"
#include "geometry/types.hpp"
#include "run/run_limits.hpp"
#include "scene/scene.hpp"

namespace cairn {

/// Options of one run that are not part of the scene file.
struct RunOptions {
    std::string contact_mode = "rigid";   ///< reference engines: "rigid" or "matched"
    RunLimits limits;                     ///< what the run may cost (steps, rows, memory, dt)
    bool record_contacts = false;         ///< keep per-point contact forces for contact_points()
};

/// Pose and velocity of one free block, world frame.
struct BlockState {
    Vec3 position = Vec3::Zero();          ///< centre of mass, m
    Quat orientation = Quat::Identity();   ///< rotation block frame → world
    Vec3 velocity = Vec3::Zero();          ///< centre-of-mass velocity, m/s
    Vec3 angular_velocity = Vec3::Zero();  ///< rad/s
};

/// Energy bookkeeping, J. balance_error() closes to ~0 for a consistent integrator.
struct Energies {
    double kinetic = 0.0;      ///< J
    double potential = 0.0;    ///< gravity, J (zero at the world origin)
    double contact = 0.0;      ///< stored in contact springs, J
    double strain = 0.0;       ///< stored in deformable blocks, J
    double dissipated = 0.0;   ///< friction, contact and mass/stiffness damping so far, J
    double external = 0.0;     ///< work done by loads so far, J
    /// total energy at t = 0 minus total now, with dissipation and external work accounted, J
    double total() const { return kinetic + potential + contact + strain + dissipated - external; }
};

/// What a backend reports at one instant.
struct Sample {
    double t = 0.0;                   ///< s
    std::vector<Vec3> probes;         ///< world positions of Scene::probes, m
    std::vector<BlockState> blocks;   ///< one per free block, in Scene::blocks order
    Energies energy;
    int contacts = 0;                 ///< active contact points (or engine contacts)
};

/// One contact point and the force it carries, world frame.
struct ContactPoint {
    Vec3 position = Vec3::Zero();      ///< the point, m
    Vec3 normal = Vec3::UnitZ();       ///< unit contact normal, from block_b towards block_a
    Vec3 normal_force = Vec3::Zero();  ///< normal part of the force on block_a, N
    Vec3 shear_force = Vec3::Zero();   ///< tangential (friction) part of the force on block_a, N
    int block_a = -1;                  ///< Scene::blocks index of one block (-1: unknown)
    int block_b = -1;                  ///< Scene::blocks index of the other (-1: unknown)
};

/// The current mesh of a deformable block, world frame.
struct BlockMesh {
    std::vector<Vec3> nodes;                    ///< node positions, m
    std::vector<Vec3> velocities;               ///< node velocities, m/s (one per node)
    std::vector<std::array<int, 8>> elements;   ///< node indices in hex8 corner order
};

/// Result of advancing one step.
enum class StepStatus { ok, unstable };

/// A simulation engine behind the common scene interface.
class Backend {
public:
    virtual ~Backend() = default;
    /// registry name ("dem", "bullet", ...)
    virtual std::string name() const = 0;
    /// engine name and version, for run.json
    virtual std::string engine_version() const = 0;
    /// build the model of `scene`; throws cairn::Error naming what cannot be represented
    virtual void build(const Scene& scene, const RunOptions& options) = 0;
    /// the time step used, s
    virtual double time_step() const = 0;
    /// the critical (stability-limit) step estimated for this model, s; 0 when unknown
    virtual double critical_step() const = 0;
    /// advance one time step
    virtual StepStatus step() = 0;
    /// the current state
    virtual Sample sample() const = 0;
    /// why the last step was unstable (empty otherwise)
    virtual std::string failure() const { return {}; }
    /// approximations made for this scene and the parameters actually used, as "key: value" lines
    virtual std::vector<std::string> notes() const { return {}; }
    /// contact points of the current state with their forces, N (default: none exposed)
    virtual std::vector<ContactPoint> contact_points() const { return {}; }
    /// current mesh of Scene::blocks[block] when the block is deformable; empty otherwise (default)
    virtual BlockMesh block_mesh(int block) const { (void)block; return {}; }
};

}  // namespace cairn
