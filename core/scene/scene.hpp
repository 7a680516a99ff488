#pragma once
/// The scene: plain data, validated once on load (scene_io.hpp), read by every backend.
/// SI units throughout; every field says its unit.

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "geometry/types.hpp"

namespace cairn {

/// How a block's shape was given.
enum class Shape { box, hexahedron };

/// What model a backend uses for a block.
enum class BlockModel { rigid, deformable };

/// How a deformable block's mass is assembled.
enum class MassScheme { lumped, consistent, barycentre, corrected };

/// How the contact damping value is read.
enum class ContactDampingRule {
    none,       ///< no contact damping
    ratio,      ///< ζ: fraction of critical damping of the face spring kn·A on the pair's reduced mass
    time,       ///< γ (s): dashpot c = γ·k for each contact spring (the paper's C = γ·Kc)
};

/// How the in-house engine finds and integrates contact (docs/dem.md).
enum class ContactScheme {
    overlap,    ///< the penalty integrated over the overlap of facing faces, n×n sub-contacts per face
    paper,      ///< the paper's node-to-face rule on a grid of virtual hitting points (grid_spacing)
};

/// An elastic isotropic material.
struct Material {
    std::string name;
    double density = 0.0;   ///< kg/m³
    double young = 0.0;     ///< Young's modulus, Pa
    double poisson = 0.0;   ///< Poisson ratio, dimensionless, in (-1, 0.5)
};

/// Mesh of a deformable block (used when model = deformable).
struct MeshDef {
    std::array<int, 3> divisions{1, 1, 1};   ///< hex8 elements along the block-frame axes
    MassScheme mass = MassScheme::corrected; ///< mass assembly (corrected: exact rotational inertia at any mesh)
    std::vector<int> fixed_nodes;            ///< node indices held at rest (mesh numbering, docs/scenes.md)
    bool fix_base = false;                   ///< hold every node of the bottom face (ζ = -1 face) at rest
};

/// One block: a convex hexahedron with 8 corners in its own block frame.
struct BlockDef {
    std::string name;
    Shape shape = Shape::box;
    Vec3 size = Vec3::Zero();            ///< box edge lengths along the block-frame axes, m (box only)
    std::array<Vec3, 8> corners;         ///< corners in the block frame, m, hex8 order (boxes too)
    Vec3 position = Vec3::Zero();        ///< world position of the block-frame origin at t = 0, m
    Quat orientation = Quat::Identity(); ///< rotation block frame → world at t = 0
    Vec3 velocity = Vec3::Zero();        ///< initial velocity of the centre of mass, m/s (world)
    Vec3 angular_velocity = Vec3::Zero();///< initial angular velocity, rad/s (world)
    int material = 0;                    ///< index into Scene::materials
    bool fixed = false;                  ///< true: no degrees of freedom, never moves
    BlockModel model = BlockModel::rigid;
    MeshDef mesh;                        ///< used when model = deformable
};

/// The contact law shared by every pair of blocks (paper: penalty normal, elastic-Coulomb shear).
struct ContactLaw {
    double kn = 0.0;            ///< normal penalty stiffness per unit area, N/m³
    double ks = 0.0;            ///< shear stiffness per unit area, N/m³
    double friction = 0.0;      ///< Coulomb coefficient μ, dimensionless
    ContactDampingRule damping_rule = ContactDampingRule::none;
    double damping = 0.0;       ///< ζ (dimensionless) or γ (s), per damping_rule
    double restitution = 0.0;   ///< for rigid-contact engines only: coefficient of restitution
    double grid_spacing = 0.1;  ///< paper scheme: largest spacing of hitting points on a face, m
    ContactScheme scheme = ContactScheme::overlap;  ///< in-house engine: how contact is integrated
    int subdivision = 4;        ///< overlap scheme: sub-contacts per edge of a hitting face (n×n), count
};

/// Rayleigh-type damping of the blocks' motion.
struct Damping {
    double alpha = 0.0;   ///< mass-proportional coefficient α, 1/s (C = α·M)
    double beta = 0.0;    ///< stiffness-proportional coefficient β, s (C = β·K; deformable only)
};

/// A time history sampled at increasing times, linearly interpolated, zero outside its span.
struct TimeSeries {
    std::vector<double> time;    ///< s, strictly increasing
    std::vector<double> value;   ///< one value per time, in the unit of its use
    /// the value at time t (s)
    double at(double t) const;
};

/// One component of the ground acceleration: a record along a fixed world direction.
struct GroundComponent {
    TimeSeries acceleration;          ///< m/s² along `direction` (units and scale applied)
    Vec3 direction = Vec3::UnitX();   ///< unit vector, world
    std::string source;               ///< the CSV file (and column) it came from, or "inline"
};

/// Ground acceleration: the fixed blocks are the ground, and the scene is solved in the ground's
/// frame, so every free block feels the inertial force −m·a_g(t) (loads generated on load); a
/// vertical component changes the effective gravity to g + a_z.
struct GroundMotion {
    std::vector<GroundComponent> components;   ///< one record along `direction`, or up to 3 along x, y, z
    double start = 0.0;               ///< s: the records' t = 0 falls at this scene time
};

/// A force on a block at a material point; its direction is fixed in the world.
struct LoadDef {
    int block = 0;                ///< index into Scene::blocks
    Vec3 force = Vec3::Zero();    ///< N, world frame
    Vec3 point = Vec3::Zero();    ///< point of application in the block frame, m
    double ramp = 0.0;            ///< s: force grows linearly from 0 over this time; 0 = applied at once
    double start = 0.0;           ///< s: the load acts from this time on
    /// if set, the force is also scaled by this history at (t − start) (ground motion)
    std::shared_ptr<const TimeSeries> history;
    /// true: a body force spread like the block's mass (ground motion); false: at `point`
    bool body = false;
    /// magnitude factor at time t (0 before start, linear ramp, then 1; times the history)
    double factor(double t) const {
        if (t < start) return 0.0;
        double f = ramp <= 0.0 ? 1.0 : std::min(1.0, (t - start) / ramp);
        return history ? f * history->at(t - start) : f;
    }
};

/// A named material point of a block, recorded by every backend.
struct ProbeDef {
    std::string name;
    int block = 0;               ///< index into Scene::blocks
    Vec3 point = Vec3::Zero();   ///< block frame, m
};

/// Time stepping and output.
struct RunControl {
    double duration = 1.0;            ///< simulated time, s
    std::optional<double> dt;         ///< time step, s; empty = auto (see the safety factors)
    double dt_safety = 0.1;           ///< dt = auto: fraction of the contact springs' critical step
    double element_dt_safety = 0.8;   ///< dt = auto: fraction of the elements' critical step (deformable)
    double output_interval = 1e-3;    ///< time between trajectory rows, s (rounded to whole steps)
    int contact_interval = 10;        ///< steps between contact-pair refreshes (n)
    std::optional<double> contact_margin;  ///< broad-phase margin, m; empty = auto
    bool settle = true;               ///< penalty engines: bring the blocks to rest under gravity and the loads at t = 0 before t = 0
};

/// The analytic reference the scene is meant to match (read by the compare layer).
struct ReferenceDef {
    std::string kind;                      ///< e.g. "rest", "impact", "slide", "stick", "housner"
    int block = -1;                        ///< index into Scene::blocks of the block it describes
    std::map<std::string, double> values;  ///< named parameters of the reference, SI units
};

/// One value of a backend's own settings table, with where it came from.
struct Setting {
    std::variant<bool, long long, double, std::string> value;
    std::string origin;   ///< "file:line" or "--set"
};

/// The whole scene.
struct Scene {
    std::string name;                      ///< scene name (defaults to the file stem)
    std::string description;               ///< free text
    std::string source;                    ///< path of the scene file
    Vec3 gravity{0.0, 0.0, -9.81};         ///< m/s²
    std::vector<Material> materials;
    ContactLaw contact;
    Damping damping;
    std::vector<BlockDef> blocks;          ///< in name order
    std::vector<LoadDef> loads;            ///< given loads, then those of the ground motion
    std::optional<GroundMotion> ground_motion;
    std::vector<ProbeDef> probes;          ///< in name order
    RunControl run;
    std::optional<ReferenceDef> reference;
    /// per-backend settings tables: backend name → key → value (validated by that backend)
    std::map<std::string, std::map<std::string, Setting>> backend_settings;

    /// index of the block with this name, or -1
    int block_index(const std::string& block_name) const;
};

/// Names of enum values as they appear in scene files.
const char* to_string(Shape s);
const char* to_string(BlockModel m);
const char* to_string(MassScheme m);
const char* to_string(ContactDampingRule r);
const char* to_string(ContactScheme s);

}  // namespace cairn
