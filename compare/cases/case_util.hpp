#pragma once
/// Helpers shared by the case analyses: block mass, contact face area, signals from samples.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "analytic/oracles.hpp"
#include "backend/backend.hpp"
#include "cases/case_analysis.hpp"
#include "metrics/metric.hpp"
#include "metrics/signal.hpp"

namespace cairn::cases {

/// one side of a placed block: its outward unit normal and one of its corners, world
struct PlacedSide {
    Vec3 normal, corner;
};
/// the six sides of block b where the scene places it (kFaceCorners order)
std::array<PlacedSide, 6> placed_sides(const BlockDef& b);


/// mass of block `b` of the scene, kg
double block_mass(const Scene& scene, int b);
/// area of the bottom face (corners 0-3) of block `b`, m²
double bottom_area(const Scene& scene, int b);
/// the smaller bottom-face area of the reference block and the first fixed block, m² (the face-on-
/// face contact area of the paper's stacked cases)
double contact_area(const Scene& scene);
/// the reference block's applied force per unit mass at time t (m/s², world): every load on it,
/// a ground motion's −m·a_g among them (point loads as if at the centre of mass); it reads
/// `scene`, which must outlive it
std::function<Vec3(double)> reference_drive(const Scene& scene);
/// kn·h/E of block `b`: the joints' stiffness per unit area (kn, N/m³) against the block's own
/// axial stiffness per unit area over its height h (frame z), E/h; dimensionless. Near 0 the block
/// is rigid against its joints; where it is not, a deformable block's vibration trades energy
/// with its rigid motion at every impact
double joint_to_block_stiffness(const Scene& scene, int b);
/// the largest kn·h/E at which a deformable block is judged against a rigid block's rocking after
/// its impacts: a 2 × 1.5 × 8 m pillar swings 0.9 % off the Winkler base's amplitude after its
/// second impact at 0.004 and 3.6 % at 0.013 (docs/validation.md, "A flexible block rocking")
inline constexpr double kRigidAgainstJoints = 0.005;
/// the largest kn·h/E at which a deformable block is judged against a rigid block under a ground
/// motion (ground_rocking): a 2 × 1.5 × 8 m pillar under a one-sine pulse uplifts within 2.7 ms of
/// the Winkler base and peaks within 0.1 % at 1.33; at 4 it uplifts 10 ms late and peaks 14 % lower
inline constexpr double kRigidUnderDrive = 1.0;
/// the same for a frame's members (its columns and beam): the trilithon of earthquake/
/// frame_pulse_rock under El Centro × 1.5, deformable, uplifts 6.0 ms before the Winkler frame
/// (tolerance 3.8 ms) at kn·h/E = 0.53 and within 0.1 ms at 0.053
inline constexpr double kFrameRigidUnderDrive = 0.1;
/// why a deformable block's rocking is shown and not judged, or empty when its kn·h/E is within
/// `limit` (kRigidAgainstJoints for its swings after an impact), or the variant's block is rigid
std::string flexible_block_reason(const Scene& scene, int b, bool deformable, double limit = kRigidAgainstJoints);
/// ks·h/G of block `b`: the joints' shear stiffness per unit area (ks, N/m³) against the block's
/// own shear stiffness per unit area over its height h (frame z), G/h with G = E/(2(1 + ν));
/// dimensionless
double joint_to_block_shear(const Scene& scene, int b);
/// the largest ks·h/G at which a deformable block's base shear is judged against a rigid block on
/// its springs (stick): its own shear adds about 11 × ks·h/G % to its base centre's displacement (a
/// 3.1 × 4.2 × 4.6 m block under 0.12 W at ks = 1.05e10: +0.04 / +0.44 / +4.4 / +44 % at
/// ks·h/G = 0.0039 / 0.039 / 0.39 / 3.9, session 37), so 0.6 % here, a fifth of the 3 % tolerance
inline constexpr double kRigidInShear = 0.05;
/// turns the judged metrics of a deformable block compliant against its joints (kn·h/E above
/// kRigidUnderDrive: a sliding block's own vibration, which the rigid sliding block leaves out,
/// takes part in its slide: +6.6 % on a 2.5 m tall block at 2.25, +0.16 % at 0.225, session 37)
/// into ones shown with the reason; a rigid variant's are left as they are
void show_if_flexible(const Scene& scene, const ContactKind& contact, std::vector<metrics::Metric>& metrics);
/// |gravity|, m/s²
double gravity(const Scene& scene);
/// v as "[x, y, z]" for a message, 4 significant digits each
std::string message_vector(const Vec3& v);
/// index of the reference block among the free blocks (Sample::blocks order)
int free_index(const Scene& scene, int block);
/// index of probe `name`, or -1
int probe_index(const Scene& scene, const std::string& name);
/// contact dashpot of the scene's damping rule for a spring K on mass m (ratio: 2ζ√(Km); time: γK), N·s/m
double dashpot(const Scene& scene, double stiffness, double mass);

/// the rocking axis of a housner reference (its axis_x/y/z values; default y), unit, world
Vec3 rocking_axis(const Scene& scene);
/// the same axis in the reference block's frame (whose z is its height when upright)
Vec3 rocking_axis_block(const Scene& scene);
/// refuses a tilted release (housner, winkler_rocking) the oracle does not describe, naming the
/// kind: a rocking axis off the horizontal, or a block whose frame z does not lean θ0 from the
/// vertical about that axis (1e-3 rad), a block on a free block, or one touched by another free block
void require_tilted_release(const Scene& scene, const std::string& kind);
/// refuses, naming `kind`, a reference block that another free block touches (their gap within 1 %
/// of its height: a block on it, under it or beside it, as a brick in a wall): the single-block
/// oracles model one block alone on a fixed base
void require_alone(const Scene& scene, const std::string& kind);
/// Housner's block of the reference block: half-width across the rocking axis and half-height,
/// from its corners in the block frame
oracle::HousnerBlock housner_block(const Scene& scene);
/// the same about the unit block-frame axis `axis` (horizontal)
oracle::HousnerBlock housner_block(const Scene& scene, const Vec3& axis);
/// throws cairn::Error naming `kind` unless gravity is along −z and the first fixed block (the
/// base) stands upright within 1e-3 rad
void require_horizontal_base(const Scene& scene, const std::string& kind);

/// the turn (world) that brings the scene's gravity onto −z: identity when it runs along −z already
Quat gravity_down(const Scene& scene);
/// the scene turned whole by `r` (world): its blocks' places, orientations and speeds, gravity, the
/// loads and the ground motion's directions (block-frame data, probes and load points, stay)
Scene turned_scene(const Scene& scene, const Quat& r);
/// a run's samples turned whole by `r` (world), as turned_scene turns its scene
std::vector<Sample> turned_samples(const std::vector<Sample>& s, const Quat& r);

/// what a kind's oracle models of the scene's drive, beyond gravity
struct DriveModelled {
    bool loads_on_reference = false;   ///< the `[loads]` on the reference block (no other load)
    bool initial_velocity = false;     ///< the reference block's initial velocity and angular velocity
};
/// throws cairn::Error naming `kind` and the key when the scene drives its blocks in a way the
/// kind's oracle leaves out: a `[ground_motion]`, a load it does not model, or an initial velocity
void require_drive_modelled(const Scene& scene, const std::string& kind, DriveModelled modelled);

/// component c (0 x, 1 y, 2 z) of probe p, minus its value at t = 0 when `relative`
metrics::Series probe_series(const std::vector<Sample>& s, int p, int c, bool relative);
/// component c of the centre of mass of free block f, minus its value at t = 0 when `relative`
metrics::Series com_series(const std::vector<Sample>& s, int f, int c, bool relative);
/// the unit vector against gravity (exactly +z for gravity along −z; zero without gravity)
Vec3 up_direction(const Scene& scene);
/// rise against gravity since the first sample, m: of probe p, or of free block f's centre where p < 0
metrics::Series rise_series(const Scene& scene, const std::vector<Sample>& s, int p, int f);
/// signed rotation angle (rad) of free block f about the unit world axis, from the orientation
/// `from` (world; identity: from the world's axes), unwrapped to be continuous in time
metrics::Series angle_series(const std::vector<Sample>& s, int f, const Vec3& axis, const Quat& from = Quat::Identity());
/// the reference block of a tilted release (housner, winkler_rocking) stood upright: its scene
/// orientation turned back by its lean about the rocking axis, so that its tilt is measured from
/// the upright block in any world (gravity along −y, a rocking axis the world turned about)
Quat upright_orientation(const Scene& scene);
/// the sample times
std::vector<double> times(const std::vector<Sample>& s);

/// "slip while held": the drift of a held block's displacement `s` (m) over [t0, t1], its ringing
/// taken out (metrics::held_drift, noise a quarter of `tol`), within `tol` (m) of 0; shown and not
/// judged where the ringing hides it. `basis` ends the explanation; `held` receives the drift
metrics::Metric slip_while_held(const metrics::Series& s, double t0, double t1, double tol, const std::string& basis,
                                metrics::HeldDrift* held = nullptr);

}  // namespace cairn::cases
