#pragma once
/// Helpers shared by the two contact schemes: which side of a pair hits which, where a force is
/// applied on a block (weights of its nodes), and the dashpot coefficients.

#include <array>
#include <vector>

#include "block.hpp"
#include "scene/scene.hpp"

namespace cairn::dem {

/// The sides of one block for one step: outward unit normals and centres (m) of its 6 sides.
struct SideFrames {
    std::array<Vec3, 6> normal;
    std::array<Vec3, 6> centre;
    /// the frames of block b's sides at its current nodes
    static SideFrames of(const Block& b);
};

/// The target rule's ties by geometry held through a contact: equal sides of equal blocks that
/// touch keep the roles they took when they first touched, until they part (docs/dem.md, the
/// choice of sides). Where the two sides meet at an angle the two directions' overlap
/// integrals differ, and a swap in contact made or lost their difference in one step (a voussoir
/// hinged 19° open on its neighbour lost 14 J of spring energy as the rule's deciding axis
/// changed from z to x).
struct TieMemory {
    /// (hitting block, its side, target block, its side) of every tie in contact, sorted
    std::vector<std::array<int, 4>> kept;
    /// per block b, its entries as hitting block: kept[first[b]] up to kept[first[b + 1]]
    std::vector<int> first;
    /// +1: side hs of block h hits side ts of block t; −1: the reverse; 0: not kept
    int role(int h, int hs, int t, int ts) const;
    /// sort `kept` and index it by hitting block, for `blocks` blocks
    void index(size_t blocks);
};

/// true when sides `hit_side` of block h and `target_side` of block t tie on area, fixity and
/// volume, so that the target rule decides between them by geometry
bool tie_by_geometry(const std::vector<Block>& blocks, int h, int hit_side, int t, int target_side);

/// true when the geometric rule for sides of outward normals nh (hitting) and nt (target) is near
/// its switch: it flips only where a component of m = n_t − n_h crosses half of |m|, and one lies
/// within a tenth of that (a pair turns far less in a step). Ties are kept from there on
bool near_tie_switch(const Vec3& nh, const Vec3& nt);

/// The sides of a (hitting, target) block pair for one step.
struct PairGeometry {
    const TieMemory* ties = nullptr; ///< ties kept through a contact (none: the geometric rule alone)
    std::array<Vec3, 6> normal;      ///< target sides' outward unit normals
    std::array<Vec3, 6> centre;      ///< target sides' centres, m
    std::array<int, 6> best_side{};  ///< paper scheme, per target side: the hitting block's side most opposed to it (-1: none)
    std::array<char, 6> target_ok{}; ///< paper scheme, per target side: it is the target of that hitting side
    double flush_tol = 0.0;          ///< a point this far outside a side plane is still over the side, m
    double closer_tol = 0.0;         ///< another side this much closer: the point enters through it, m
    int hit = -1, target = -1;       ///< the pair it was set for (-1: none yet)
    /// the geometry of the pair (h hits t) from every block's side frames of this step; `paper`:
    /// also the paper scheme's best sides
    void set(const std::vector<Block>& blocks, const std::vector<SideFrames>& frames, int h, int t, bool paper);
    /// set it for the pair unless already set for it (candidates of one pair come in a row);
    /// true when it changed
    bool update(const std::vector<Block>& blocks, const std::vector<SideFrames>& frames, int h, int t,
                bool paper = false) {
        if (h == hit && t == target) return false;
        set(blocks, frames, h, t, paper);
        return true;
    }
    /// paper scheme: a point not in contact with target side `side` at the last evaluation (dist:
    /// its signed distances to the 6 side planes, m, outward positive) enters through that side
    /// only if no other side plane is nearer by more than the flush tolerance plus `travel` (m, the
    /// point's move relative to the target in the step): a point first found deeper behind `side`
    /// than behind another side came in through that other side (docs/dem.md)
    bool enters_through(const double (&dist)[6], int side, double travel) const {
        for (int s = 0; s < 6; ++s)
            if (s != side && dist[s] > dist[side] + flush_tol + travel) return false;
        return true;
    }
    /// true when a point with these side distances (m) lies clearly inside the target: behind
    /// every side plane by more than the flush tolerance (a point on its surface is not)
    bool within(const double (&dist)[6]) const {
        for (double d : dist)
            if (!(d < -flush_tol)) return false;
        return true;
    }
    /// true when side `hit_side` of the hitting block hits some side of the target (paper scheme)
    bool acts(int hit_side) const {
        for (int s = 0; s < 6; ++s)
            if (best_side[s] == hit_side && target_ok[s]) return true;
        return false;
    }
    /// overlap scheme, per target side: side `hit_side` of the hitting block faces it (normals
    /// opposed) and it is the target; every side of the hitting block's lower surface seen from a
    /// target side hits it, so their shadows tile the overlap without gap or double count.
    /// Worked out on first use for each hitting side
    const std::array<char, 6>& faces(int hit_side);

private:
    const std::vector<Block>* blocks_ = nullptr;
    const std::array<Vec3, 6>* hit_normal_ = nullptr;   // the hitting block's side normals
    std::array<std::array<char, 6>, 6> faces_{};
    std::array<char, 6> faces_done_{};
};

/// the refresh's bound on the target rule (docs/dem.md): false only when side `target_side` of
/// block t is not the target of side `hit_side` of block h for any outward normals within `turn`
/// (rad, small) of nh and nt (the rule's geometric tie-break is the only part that can change)
bool may_be_target(const std::vector<Block>& blocks, int h, int hit_side, int t, int target_side, const Vec3& nh,
                   const Vec3& nt, double turn, const TieMemory* ties = nullptr);

/// damping coefficients per unit contact area (N·s/m³) of the normal and the shear dashpots
std::array<double, 2> dashpot_per_area(const ContactLaw& law, const Block& hb, const Block& tb, int hit_side);

/// spread a force (N) at natural coordinates xi of boundary face k of block b to the face nodes
void spread(Block& b, int k, const Vec2& xi, const Vec3& force);

/// Weights of the nodes of a block that apply a force at one world point: Σw = 1 and
/// Σ w·x_node = the point, so the force and its moment about any point are exact. Rigid blocks:
/// barycentric weights of 4 corners; deformable: the hex8 shape functions of the element under
/// the face, at the point's natural coordinates there.
struct NodeWeights {
    int count = 0;               ///< nodes used (4 or 8)
    std::array<int, 8> node{};   ///< node indices
    std::array<double, 8> w{};   ///< weights, dimensionless
    NodeWeights() = default;
    /// copies the nodes in use (the rest stay zero): a copy of the whole would read back, in wide
    /// loads, a set just written entry by entry, which stalls the store-to-load forwarding
    NodeWeights(const NodeWeights& o) : count(o.count) {
        for (int i = 0; i < count; ++i) node[size_t(i)] = o.node[size_t(i)], w[size_t(i)] = o.w[size_t(i)];
    }
    NodeWeights& operator=(const NodeWeights& o) {
        count = o.count;
        for (int i = 0; i < 8; ++i) {
            node[size_t(i)] = i < count ? o.node[size_t(i)] : 0;
            w[size_t(i)] = i < count ? o.w[size_t(i)] : 0.0;
        }
        return *this;
    }
    /// the velocity of the block's material at the point, m/s
    Vec3 velocity(const Block& b) const {
        Vec3 v = Vec3::Zero();
        for (int i = 0; i < count; ++i) v += w[i] * b.v[node[i]];
        return v;
    }
    /// add `force` (N) at the point to the block's node forces
    void add(Block& b, const Vec3& force) const {
        for (int i = 0; i < count; ++i) b.f[node[i]] += w[i] * force;
    }
};

/// the weights that put a force at world point x on block b (face: the boundary face nearest x)
NodeWeights node_weights(const Block& b, int face, const Vec3& x);

/// The weights of the 4 nodes of a deformable target face q (its nodes `nodes`) whose forces along
/// n at xs are the gradient of an energy that sees the face only through its plane (centre c,
/// unit normal n at the centre): Σw = 1 and Σw·q = xs projected on the plane
NodeWeights plane_weights(const Quad& q, const std::array<int, 4>& nodes, const Vec3& c, const Vec3& n, const Vec3& xs);

/// A couple as a pair of opposite forces: `force` at `centre` + `offset` and −force at
/// `centre` − offset, their moment τ (docs/dem.md, overlap scheme)
struct ForcePair {
    Vec3 offset = Vec3::Zero();   ///< half the pair's arm, m
    Vec3 force = Vec3::Zero();    ///< N
};
/// the pair of arm `arm` (m) whose moment is tau (N·m, not zero), its forces square to tau and to
/// `line` (a direction the forces should cross, e.g. a face normal; another axis where it is along tau)
ForcePair couple_as_pair(const Vec3& tau, const Vec3& line, double arm);

/// barycentric coordinates of x in the triangle (x0, x1, x2), all on a plane of unit normal n
std::array<double, 3> barycentric(const Vec3& x, const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& n);

/// adds scale × the weights on a face's 4 nodes of point x of a planar triangle on the face to w:
/// x's barycentric weights in the triangle (corners t, unit normal n), each corner spread by the
/// face's bilinear weights at its natural coordinates xi
void add_triangle_weights(const std::array<Vec3, 3>& t, const std::array<Vec2, 3>& xi, const Vec3& x, const Vec3& n,
                          double scale, std::array<double, 4>& w);

/// the 4 nodes of boundary face `face` of block b with weights w
NodeWeights face_node_weights(const Block& b, int face, const std::array<double, 4>& w);

}  // namespace cairn::dem
