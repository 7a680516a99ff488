#pragma once
/// Limit analysis of any assembly of rigid convex hexahedral blocks (Heyman, Livesley: rigid
/// blocks, no tension, infinite compressive strength, Coulomb friction): the largest multiplier λ
/// of a live load for which a statically admissible set of contact forces exists. The contacts are
/// the face-to-face interfaces of the given configuration (block_interfaces.hpp), each a set of
/// forces at the vertices of its contact polygon inside the friction pyramid inscribed in the cone
/// |t| ≤ μ·n (8 edges on the cone at k·π/4 from the live load's direction in the joint's plane).
/// The static theorem with this associative friction: exact for mechanisms of pure rocking; where
/// sliding takes part, the true (non-associative) collapse load can be lower.
/// A linear programme solved by GLPK's primal simplex, by column generation: the pyramids' edges
/// along ±t1 first, the others priced in while one would raise λ (the optimum is that of the whole
/// programme). GLPK keeps its state per thread (thread-local in Debian's build) and its terminal
/// output is switched off on each call; concurrent calls from several threads are not tested.

#include <limits>
#include <vector>

#include "geometry/hexahedron.hpp"
#include "scene/scene.hpp"

namespace cairn::oracle {

/// one block of the assembly
struct LimitBlock {
    Corners corners;              ///< world corners, m, hex8 order (hexahedron.hpp)
    double mass = 0.0;            ///< kg
    Vec3 centre = Vec3::Zero();   ///< centre of mass, world, m
    bool fixed = false;           ///< true: the ground, takes any force
};

/// a free block's virtual motion in the collapse mechanism (the duals of its equilibrium rows)
struct LimitTwist {
    Vec3 velocity = Vec3::Zero();   ///< of its centre of mass, dimensionless: the largest over the blocks is 1
    Vec3 angular = Vec3::Zero();    ///< angular velocity in the same scale, 1/m
};

/// λ above which the live load counts as carried without limit
constexpr double kLimitLambdaCap = 1e3;
/// the most free blocks the analysis takes (a wall of 916 bricks took 60–100 s): more is refused
constexpr long kLimitMaxFreeBlocks = 2000;

/// what the linear programme found
struct LimitAnalysisResult {
    /// the largest λ ≥ 0 with a statically admissible state; +inf when kLimitLambdaCap is admissible
    /// (e.g. the live load is carried by fixed blocks alone); NaN when no λ ≥ 0 is
    double lambda = std::numeric_limits<double>::quiet_NaN();
    bool stands_at_zero = false;        ///< a statically admissible state exists under gravity alone
    int interfaces = 0;                 ///< contact interfaces found, count
    int contact_points = 0;             ///< vertices of their polygons, count
    std::vector<LimitTwist> mechanism;  ///< per block, input order (zero for fixed ones); empty
                                        ///< unless λ is finite
};

/// the collapse multiplier of the blocks under gravity (m/s², world) and the live load λ·m·live
/// on every free block (live in m/s², world), with friction coefficient μ ≥ 0 on every joint and
/// every joint's contact polygon moved `inset` (m) inward from its edges (0: the rigid joints; a
/// compliant contact hinges inside its edge); throws cairn::Error on bad input or when GLPK fails
LimitAnalysisResult collapse_multiplier(const std::vector<LimitBlock>& blocks, const Vec3& gravity,
                                        const Vec3& live, double friction, double inset = 0.0);

/// the scene's blocks as LimitBlocks: world corners at t = 0, mass and centre from the material's
/// density
std::vector<LimitBlock> limit_blocks(const Scene& scene);

}  // namespace cairn::oracle
