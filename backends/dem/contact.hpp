#pragma once
/// Contact of the in-house engine: candidate (hitting face, target block) pairs found from
/// bounding boxes every n steps; each step either scheme (docs/dem.md) turns them into forces:
/// - overlap: each hitting face is cut into n×n sub-cells; a sub-cell's part behind the target
///   face and over it carries the exact integral of kn·d (closed form) at its pressure centre,
///   and an elastic-then-Coulomb shear spring from its own stick anchor at its area's centroid;
/// - paper: the paper's node-to-face rule on a grid of hitting points, each with a penalty normal
///   force and a shear spring from a stick anchor in the target face's natural coordinates.

#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "block.hpp"
#include "broad_phase.hpp"
#include "contact_pair.hpp"
#include "scene/scene.hpp"

namespace cairn::dem {

/// What a hitting point did at the last evaluation, for the step in which it enters or leaves
/// contact (docs/dem.md, Energy: contact events).
struct PointTrack {
    double depth = std::numeric_limits<double>::quiet_NaN();  ///< signed depth behind its side, m (NaN: unknown)
    double fel = 0.0;           ///< elastic normal force kn·a·d, N (0: not in contact)
    Vec3 normal = Vec3::UnitZ();///< the target's outward normal there
    int face = -1;              ///< target boundary face of its projection
    Vec2 xi = Vec2::Zero();     ///< natural coordinates of its projection there
};

/// Stick anchor of one hitting point.
struct Anchor {
    int side = -1;              ///< target side the point acts on; -1 = not in contact
    int face = -1;              ///< target boundary face the stick point lies on
    Vec2 xi0 = Vec2::Zero();    ///< natural coordinates of the stick point on that face
    double energy = 0.0;        ///< shear-spring energy at the last evaluation, J (dissipated on reset)
    Vec3 u = Vec3::Zero();      ///< shear-spring offset at the last evaluation, world, m
    double fd = 0.0;            ///< normal dashpot force at the last evaluation, N
    Vec3 fds = Vec3::Zero();    ///< shear dashpot force at the last evaluation, world, N
    PointTrack track;           ///< depth and normal spring of the last evaluation (kept on reset)
};

/// Torsion state of one sub-contact of the overlap scheme: the clipped area taken as a disc of its
/// size, whose elastic-then-Coulomb shear resists the relative spin about the normal (docs/dem.md,
/// "Twist of a sub-contact"). Its moment acts as a pair of opposite tangential forces.
struct SubTwist {
    double angle = 0.0;         ///< elastic twist offset, rad
    double energy = 0.0;        ///< torsion-spring energy at the last evaluation, J
    double area = 0.0;          ///< contact area it was sized with at the last evaluation, m²
    double moment = 0.0;        ///< moment about the normal on the hitting block (spring and dashpot), N·m
    double damper = 0.0;        ///< its dashpot part, N·m
    Vec3 dir = Vec3::Zero();    ///< the pair's force per unit moment (along the second tangent), 1/m
    Vec3 axis = Vec3::Zero();   ///< the unit normal it turns about
    /// on each block, the weights of the pair's first point less those of its second (one set of
    /// nodes: the face's element): the force dir·M spread by them is the couple
    NodeWeights hit, target;
};

/// Shear state of one sub-contact of the overlap scheme: the elastic offset of the stick spring,
/// built up from the relative tangential motion at the sub-contact's pressure centre.
struct SubAnchor {
    int cell = 0;               ///< sub-cell of the hitting face, v·n + u
    int target_face = 0;        ///< target boundary face
    Vec3 u = Vec3::Zero();      ///< elastic shear offset, world, m
    double energy = 0.0;        ///< shear-spring energy at the last evaluation, J (dissipated on reset)
    double area = 0.0;          ///< contact area at the last evaluation, m²
    bool seen = false;          ///< in contact at this evaluation
    double fd = 0.0;            ///< normal dashpot force at the last evaluation, N
    Vec3 fds = Vec3::Zero();    ///< shear dashpot force at the last evaluation, world, N
    double fel = 0.0;           ///< elastic normal force kn·∫d dA at the last evaluation, N (0 where clipped)
    double spring = 0.0;        ///< kn·∫d dA at the last evaluation, N, also where the dashpot cancelled it
    double stored = 0.0;        ///< normal-spring energy ½kn·∫d² dA at the last evaluation, J
    Vec3 normal = Vec3::UnitZ();///< the target's outward normal at the last evaluation
    NodeWeights hit_at, target_at;  ///< where its normal force acted at the last evaluation
    bool edged = false;         ///< edge forces on the target's edges acted at the last evaluation
    Vec3 fs = Vec3::Zero();     ///< shear force (spring and dashpot) on the hitting block at the last evaluation, N
    NodeWeights shear_hit, shear_target;  ///< where it acted
    SubTwist twist;             ///< its torsion spring about the normal
};

/// The force of one sub-contact, or the edge force of one of its edges on the target's edge,
/// kept until it is spread to the nodes: both blocks take its normal part on one line along the
/// normal and its shear part at one point (an edge force: both at its point), so the pairs are
/// collinear.
struct SubForce {
    NodeWeights hit, target;    ///< where its shear part acts on each block (the clipped area's centroid)
    Vec3 force = Vec3::Zero();  ///< on the hitting block (the target takes −force), N
    /// outward unit normal of the target side it pushes on (the target face; beyond a capped cut,
    /// that side o; an edge force, its own direction): splits it in the output
    Vec3 normal = Vec3::UnitZ();
    NodeWeights hit_n, target_n;///< where its normal part acts (the pressure centre; docs/dem.md "scheme = overlap")
    bool twist = false;         ///< a sub-contact's twisting couple, spread by weight differences (not a contact point)
    /// add it to the node forces of the hitting block `hb` and the target `tb`: the normal part at
    /// hit_n/target_n, the rest at hit/target (one order of sums: the same bits wherever it is spread)
    void spread(Block& hb, Block& tb) const {
        if (twist) {
            hit.add(hb, force);
            target.add(tb, -force);
            return;
        }
        spread(hit, target, force, normal, hit_n, target_n, hb, tb);
    }
    /// the same for a force given by its parts (no SubForce built)
    static void spread(const NodeWeights& hit, const NodeWeights& target, const Vec3& force, const Vec3& normal,
                       const NodeWeights& hit_n, const NodeWeights& target_n, Block& hb, Block& tb) {
        const Vec3 fn = force.dot(normal) * normal;
        hit_n.add(hb, fn);
        target_n.add(tb, -fn);
        hit.add(hb, force - fn);
        target.add(tb, fn - force);
    }
    /// keep a force (`keep` given) or spread it at once
    static void put(std::vector<SubForce>* keep, const NodeWeights& hit, const NodeWeights& target, const Vec3& force,
                    const Vec3& normal, const NodeWeights& hit_n, const NodeWeights& target_n, Block& hb, Block& tb) {
        if (keep) keep->push_back(SubForce{hit, target, force, normal, hit_n, target_n});
        else spread(hit, target, force, normal, hit_n, target_n, hb, tb);
    }
};

/// A penetration of this fraction of the smaller block's shortest edge is no longer a contact:
/// the run stops (World::step)
constexpr double kSankDepth = 0.25;

/// Energies and counts of one contact evaluation.
struct ContactTotals {
    double stored = 0.0;      ///< elastic energy in the normal and shear springs, J
    double dissipated = 0.0;  ///< this step: slip and dashpots, J
    int active = 0;           ///< penetrating hitting points
    /// penetration as a fraction of the smaller block's shortest edge (exact from kSankDepth up;
    /// below it the overlap scheme may give a bound)
    double worst_depth = 0.0;
    int worst_hit = -1, worst_target = -1;  ///< the blocks of that deepest point
};

/// The force of one penetrating hitting point, kept until it is spread to the nodes.
struct PointForce {
    int point = 0;              ///< index among the hitting face's points
    int target_face = 0;        ///< target boundary face it acts on
    Vec2 target_xi = Vec2::Zero();  ///< natural coordinates of its projection there
    Vec3 force = Vec3::Zero();  ///< on the hitting block (the target takes −force), N
};

/// The part of a contact force that acts in the end-of-step half kick only: a point or sub-contact
/// that entered or left contact inside the step gets the impulse of the part of the step it was
/// in contact (docs/dem.md, Energy: contact events).
struct EventForce {
    int block = 0;              ///< block it acts on
    NodeWeights at;             ///< where
    Vec3 force = Vec3::Zero();  ///< N
};

/// A hitting face that may touch a target block.
struct Candidate {
    int hit_block = 0;
    int hit_face = 0;
    int target_block = 0;
    std::vector<Anchor> anchors;  ///< paper scheme: one per hitting point of the face
    std::vector<PointForce> forces;  ///< paper scheme: this step's forces, spread after every candidate
    std::vector<SubAnchor> subs;     ///< overlap scheme: anchors of the sub-contacts in contact
    std::vector<SubForce> sub_forces;///< overlap scheme: this step's forces, spread after every candidate
    std::vector<EventForce> events;  ///< this step's end-of-step corrections of points entering or leaving
    ContactTotals totals;            ///< this step's energies and counts
};


/// The contact state of a world.
class ContactSet {
public:
    /// set the law; `margin` (m) is the total broad-phase gap covered between refreshes
    void configure(const ContactLaw& law, double margin);
    /// rebuild the candidate list from bounding boxes; anchors of surviving candidates are kept
    void refresh(std::vector<Block>& blocks);
    /// add contact forces to the blocks' node forces; dt (s) scales the dashpot dissipation.
    /// Candidates are evaluated on every core, then spread in their fixed order (same bits on
    /// any number of threads)
    ContactTotals apply(std::vector<Block>& blocks, double dt);
    /// the end-of-step corrections of points that entered or left contact in this step, in the
    /// candidates' order (valid until the next apply)
    const std::vector<EventForce>& events() const { return events_; }
    /// candidate hitting faces
    const std::vector<Candidate>& candidates() const { return candidates_; }
    /// broad-phase margin, m
    double margin() const { return margin_; }
    /// change the margin (m) the next refresh grows the boxes by
    void set_margin(double margin) { margin_ = margin; }
    /// keep every point's force in its candidate (Candidate::forces) also on one thread, for output
    void keep_forces(bool keep) { keep_forces_ = keep; }
    /// overlap scheme: leave out at each refresh the faces that cannot reach their target before
    /// the next (on by default; off: every face whose box meets the target's, for comparison)
    void prune(bool on) { prune_ = on; }
    /// overlap scheme with pruning: the blocks flagged in `turned` (one flag per block) are about
    /// to turn past kRefreshTurn since the last refresh. Every face of their pairs that the refresh
    /// left out is made a candidate again, in its place in the refresh's order (the order without
    /// pruning), so that they may turn freely until the next refresh; the other pairs stay pruned
    void widen(const std::vector<char>& turned);
    /// true when block i's pairs are no longer pruned (widen) until the next refresh
    bool widened(size_t i) const { return i < widened_.size() && widened_[i] != 0; }
    /// false: no shear spring slips, whatever its normal force (the settling before t = 0
    /// finds the springs' elastic static state, which does not depend on the path); default true
    void allow_slip(bool on) { slip_ = on; }

private:
    /// candidates [begin, end): forces (kept in the candidate, or spread at once), anchors, totals
    void evaluate(std::vector<Block>& blocks, double dt, long begin, long end, bool keep_forces);
    /// the paper's node-to-face scheme on candidates [begin, end)
    void evaluate_paper(std::vector<Block>& blocks, double dt, long begin, long end, bool keep_forces);
    /// the overlap scheme on candidates [begin, end)
    void evaluate_overlap(std::vector<Block>& blocks, double dt, long begin, long end, bool keep_forces);
    /// overlap scheme: the ties by geometry in contact after this evaluation keep their roles
    void remember_ties(const std::vector<Block>& blocks);

    ContactLaw law_;
    double margin_ = 0.0;
    bool keep_forces_ = false;
    bool prune_ = true;
    bool slip_ = true;
    std::vector<Candidate> candidates_;
    TieMemory ties_;                   // overlap scheme: the ties in contact at the last evaluation
    std::vector<std::array<int, 4>> tie_order_, tie_scratch_;   // the same in the candidates' order, and the next
    std::vector<EventForce> events_;
    std::vector<SideFrames> frames_;   // every block's side frames of this step
    // buffers kept between refreshes so that a steady state allocates nothing
    std::vector<Candidate> previous_;
    std::vector<Aabb> boxes_;
    BroadPhase broad_;
    std::vector<std::pair<int, int>> pairs_;
    // overlap scheme with pruning: every face whose box met its target's at the last refresh, in
    // the refresh's order, and whether it is a candidate now; per block, whether widen lifted its
    // pruning
    struct Slot {
        int hit_block = 0, hit_face = 0, target_block = 0;
        bool active = false;
    };
    std::vector<Slot> slots_;
    std::vector<char> widened_;
    std::vector<Candidate> spare_;   // widen's scratch
};

/// true when side `target_side` of block t is the target of side `hit_side` of block h: the
/// larger face is the target; equal faces: a fixed block, then the larger block, then by
/// geometry (the lower of two stacked sides, the −x one of two side by side), never by index
/// or name
bool is_target(const std::vector<Block>& blocks, int h, int hit_side, int t, int target_side);

}  // namespace cairn::dem
