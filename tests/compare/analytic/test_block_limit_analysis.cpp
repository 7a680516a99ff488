// the limit analysis of block assemblies against closed forms and the 2-D arch oracles
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "analytic/arch_lateral.hpp"
#include "analytic/arch_thrust.hpp"
#include "analytic/block_interfaces.hpp"
#include "analytic/block_limit_analysis.hpp"
#include "analytic/stack_pushover.hpp"
#include "error.hpp"
#include "geometry/overlap.hpp"
#include "scene/arch_builder.hpp"
#include "scene/scene_io.hpp"
#include "scene/wall_builder.hpp"

using namespace cairn;
using namespace cairn::oracle;

namespace {

constexpr double kG = 9.81, kRho = 2600.0;
const Vec3 kGravity(0, 0, -kG);

/// a homogeneous box of edge lengths `size` (m) centred at `centre`, turned by `turn`
LimitBlock box(const Vec3& size, const Vec3& centre, bool fixed = false, const Quat& turn = Quat::Identity()) {
    LimitBlock b;
    b.corners = placed_corners(box_corners(size), centre, turn);
    b.mass = kRho * size.prod();
    b.centre = centre;
    b.fixed = fixed;
    return b;
}

/// a fixed 4 × 4 × 0.5 m slab whose top is z = 0
LimitBlock ground() { return box(Vec3(4, 4, 0.5), Vec3(0, 0, -0.25), true); }

/// a horizontal live load of 1 g at `angle` (rad) from +x
Vec3 push(double angle = 0.0) { return kG * Vec3(std::cos(angle), std::sin(angle), 0); }

/// the blocks of a generated scene, of density kRho
std::vector<LimitBlock> blocks_of(Scene s) {
    s.materials.push_back(Material{"stone", kRho, 30e9, 0.2});
    for (auto& b : s.blocks) b.material = 0;
    return limit_blocks(s);
}

/// a semicircular arch (R = 1 m, depth 0.5 m) on its two springers; `sectors`: each voussoir's
/// mass and centre those of the annular sector of the 2-D oracles instead of its straight-sided
/// hexahedron's (the joints, where the contacts are, are the same)
std::vector<LimitBlock> arch(int n, double t, bool sectors) {
    Scene s;
    add_arch(s, ArchSpec{n, 1.0, t, 0.5, M_PI});
    auto blocks = blocks_of(s);
    if (!sectors) return blocks;
    const double ri = 1 - 0.5 * t, re = 1 + 0.5 * t, beta = M_PI / n;
    const double rho = (2.0 / 3.0) * (re * re * re - ri * ri * ri) / (re * re - ri * ri) *
                       std::sin(0.5 * beta) / (0.5 * beta);
    for (auto& b : blocks) {
        if (b.fixed) continue;
        const Vec3 mid = Vec3(b.centre.x(), 0, b.centre.z()).normalized();   // the voussoir's mid-angle
        b.centre = rho * mid + Vec3(0, b.centre.y(), 0);
        b.mass = kRho * 0.5 * (re * re - ri * ri) * beta * 0.5;
    }
    return blocks;
}

/// the wall of scenarios/structures/wall_pushover.toml (4 courses, 0.4 × 0.2 × 0.2 m bricks)
std::vector<LimitBlock> pushover_wall() {
    return limit_blocks(load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/structures/wall_pushover.toml"));
}

/// the same wall generated (cairn make wall): 4 courses of 4 bricks, half-brick closers, on a slab
std::vector<LimitBlock> running_wall() {
    WallSpec w;
    w.courses = 4;
    w.bricks = 4;
    Scene s;
    add_wall(s, w);
    return blocks_of(s);
}

/// every corner, centre and the loads turned by q
LimitAnalysisResult turned(std::vector<LimitBlock> blocks, const Quat& q, const Vec3& live, double mu) {
    for (auto& b : blocks) {
        for (Vec3& c : b.corners) c = q * c;
        b.centre = q * b.centre;
    }
    return collapse_multiplier(blocks, q * kGravity, q * live, mu);
}

}  // namespace

TEST_CASE("limit analysis: two faces touch over their clipped overlap", "[oracle][limit]") {
    // a 0.4 m cube turned 45° about z on another: a regular octagon of area a²·(2√2 − 2)
    const LimitBlock low = box(Vec3(0.4, 0.4, 0.4), Vec3(0, 0, 0.2));
    const Quat turn(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()));
    const LimitBlock high = box(Vec3(0.4, 0.4, 0.4), Vec3(0, 0, 0.6), false, turn);
    const auto c = find_interfaces({low.corners, high.corners}, {false, false}, 1e-6);
    REQUIRE(c.size() == 1);
    CHECK(c[0].polygon.size() == 8);
    CHECK(c[0].area == Approx(0.16 * (2 * std::sqrt(2.0) - 2)).epsilon(1e-12));   // round-off only
    CHECK(c[0].normal.isApprox(-Vec3::UnitZ(), 1e-12));   // from the upper (second) into the lower
    // 1 mm apart, or touching along an edge only: no interface
    const LimitBlock apart = box(Vec3(0.4, 0.4, 0.4), Vec3(0, 0, 0.601));
    const LimitBlock edge = box(Vec3(0.4, 0.4, 0.4), Vec3(0.4, 0, 0.6));
    CHECK(find_interfaces({low.corners, apart.corners}, {false, false}, 1e-6).empty());
    CHECK(find_interfaces({low.corners, edge.corners}, {false, false}, 1e-6).empty());
    // two fixed blocks are never paired
    CHECK(find_interfaces({low.corners, high.corners}, {true, true}, 1e-6).empty());
}

TEST_CASE("limit analysis: a block on the ground tips at w/h or slides at μ", "[oracle][limit]") {
    const std::vector<LimitBlock> blocks{ground(), box(Vec3(0.4, 0.3, 1.0), Vec3(0.1, 0.2, 0.5))};
    // the programme's optimum is a vertex computed in double precision: 1e-9 relative
    const auto tip = collapse_multiplier(blocks, kGravity, push(), 2.0);
    CHECK(tip.lambda == Approx(0.4 / 1.0).epsilon(1e-9));
    CHECK(tip.stands_at_zero);
    CHECK(tip.interfaces == 1);
    CHECK(tip.contact_points == 4);
    // the mechanism: the block turns about +y (toward +x) about its leading bottom edge
    REQUIRE(tip.mechanism.size() == 2);
    const Vec3 w = tip.mechanism[1].angular;
    CHECK(w.y() > 0);
    CHECK(std::abs(w.x()) + std::abs(w.z()) < 1e-9 * w.y());
    CHECK(tip.mechanism[1].velocity.isApprox(w.cross(Vec3(-0.2, 0, 0.5)), 1e-9));
    CHECK(collapse_multiplier(blocks, kGravity, push(), 0.3).lambda == Approx(0.3).epsilon(1e-9));
    // across the block d/h; frictionless nothing at all; a live load pressing down, no limit
    CHECK(collapse_multiplier(blocks, kGravity, push(M_PI / 2), 2.0).lambda == Approx(0.3).epsilon(1e-9));
    const auto smooth = collapse_multiplier(blocks, kGravity, push(), 0.0);
    CHECK(smooth.lambda == 0.0);
    CHECK(smooth.stands_at_zero);
    CHECK(std::isinf(collapse_multiplier(blocks, kGravity, kGravity, 0.5).lambda));
}

TEST_CASE("limit analysis: a block leaning off its support needs the live load to stand", "[oracle][limit]") {
    // a 0.4 × 0.4 m block over a 0.2 m wide fixed pedestal (x ∈ [0, 0.2]) with its centre at
    // x = −0.05, 0.05 m beyond the support: it falls under gravity alone; pushed along +x it stands
    // from λ = 0.05/0.2 (about the support's rear edge) to 0.2/0.2 (over the front edge x = 0.15)
    const std::vector<LimitBlock> blocks{box(Vec3(0.2, 1, 0.5), Vec3(0.1, 0, -0.25), true),
                                         box(Vec3(0.4, 0.4, 0.4), Vec3(-0.05, 0, 0.2))};
    const auto r = collapse_multiplier(blocks, kGravity, push(), 2.0);
    CHECK_FALSE(r.stands_at_zero);
    CHECK(r.lambda == Approx(1.0).epsilon(1e-9));
    // pushed the other way nothing holds it
    const auto back = collapse_multiplier(blocks, kGravity, push(M_PI), 2.0);
    CHECK_FALSE(back.stands_at_zero);
    CHECK(std::isnan(back.lambda));
}

TEST_CASE("limit analysis: a column of drums tips at B/H along a side, √2·B/H over a corner", "[oracle][limit]") {
    std::vector<LimitBlock> column{ground()};
    for (int i = 0; i < 3; ++i) column.push_back(box(Vec3(0.4, 0.4, 0.5), Vec3(0, 0, 0.25 + 0.5 * i)));
    const double m = 0.4 * 0.4 * 0.5 * kRho;
    BlockStack stack{{{0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}, {0.5, 0.4, 0.4, m}}, kG};
    const auto side = collapse_multiplier(column, kGravity, push(), 2.0);
    CHECK(side.lambda == Approx(0.4 / 1.5).epsilon(1e-9));
    // the mechanism: the column turns as one about the base's leading edge (x = 0.2, z = 0)
    for (size_t b = 1; b < 4; ++b) {
        INFO("drum " << b);
        CHECK(side.mechanism[b].angular.isApprox(side.mechanism[1].angular, 1e-9));
        const Vec3 arm = column[b].centre - Vec3(0.2, 0, 0);
        CHECK(side.mechanism[b].velocity.isApprox(side.mechanism[b].angular.cross(arm), 1e-9));
    }
    // over a corner: the octagon pyramid's edges lie on the cone along the push, and μ = 2 keeps
    // friction from acting anyway
    stack.push_angle = M_PI / 4;
    const auto corner = collapse_multiplier(column, kGravity, push(M_PI / 4), 2.0);
    CHECK(corner.lambda == Approx(stack.rigid_multiplier()).epsilon(1e-9));
    CHECK(corner.lambda == Approx(std::sqrt(2.0) * 0.4 / 1.5).epsilon(1e-9));
}

TEST_CASE("limit analysis: the running-bond wall of wall_pushover tips out of plane at t/H", "[oracle][limit]") {
    const auto blocks = pushover_wall();
    // 18 bricks: 4 + 8 + 8 + 8 bed joints (a half-brick closer bears on one brick, a whole brick
    // of a shifted course on two), 3 + 4 + 3 + 4 head joints
    const auto r = collapse_multiplier(blocks, kGravity, push(M_PI / 2), 0.8);
    CHECK(r.interfaces == 42);
    CHECK(r.contact_points == 168);
    CHECK(r.lambda == Approx(0.2 / 0.8).epsilon(1e-9));
    // a course above a bed joint needs more: the whole wall about its base is the mechanism
    for (size_t b = 0; b < blocks.size(); ++b)
        if (!blocks[b].fixed) CHECK(r.mechanism[b].angular.isApprox(r.mechanism[1].angular, 1e-6));
}

TEST_CASE("limit analysis: an arch under a lateral load agrees with the thrust-line oracle", "[oracle][limit][arch]") {
    // with the annular sectors' masses the 3-D programme is the oracle's problem: its joints'
    // vertex forces span the same thrust positions; the oracle bisects to 1e-6 (measured 1.9e-7)
    const double oracle = ArchUnderLateralLoad{21, 0.15}.collapse_acceleration();
    const auto exact = collapse_multiplier(arch(21, 0.15, true), kGravity, push(), 1.0);
    CHECK(exact.interfaces == 22);
    CHECK(exact.lambda == Approx(oracle).margin(2e-6));
    CHECK(exact.lambda == Approx(0.14786).margin(2e-5));
    // μ = 1 and 10 agree: no joint slides (the oracle's assumption)
    const auto rough = collapse_multiplier(arch(21, 0.15, true), kGravity, push(), 10.0);
    CHECK(rough.lambda == Approx(exact.lambda).epsilon(1e-9));
    // the straight-sided voussoirs of the scenes (cairn make arch) put their centres of mass a
    // little inward: measured λ 0.14832 (+0.3 %)
    const auto straight = collapse_multiplier(arch(21, 0.15, false), kGravity, push(), 1.0);
    CHECK(straight.lambda == Approx(0.14832).margin(1e-5));
    // the least thickness of the 25-voussoir arch: standing just above it, not just below
    const double least = SemicircularArch{25}.minimum_thickness();
    CHECK(collapse_multiplier(arch(25, 1.001 * least, true), kGravity, push(), 1.0).stands_at_zero);
    const auto thin = collapse_multiplier(arch(25, 0.999 * least, true), kGravity, push(), 1.0);
    CHECK_FALSE(thin.stands_at_zero);
    CHECK(std::isnan(thin.lambda));   // no lateral load helps a symmetric arch stand
}

TEST_CASE("limit analysis: two bricks side by side lean on each other", "[oracle][limit]") {
    // bricks b = 0.2 m wide, h = 0.6 m tall side by side on the ground, pushed along their row
    // (+x). Statics per unit weight: the rear brick hangs a share s of its weight on the front one
    // through the head joint (friction s ≤ μ·p, p the head joint's thrust); the sum of the two
    // bricks' moments about their leading edges gives λ·h ≤ b·(1 + s); the rear brick's base, as
    // good as unloaded, must take the difference of its load and the thrust: |λ − p| ≤ μ·(1 − s).
    // Hence s·(μ + 1/μ) ≤ λ + μ with λ = (b/h)(1 + s), capped by s = 1 (both turn as one about
    // the front toe: 2b/h). μ = 1: s = 0.8, λ = 0.6; μ = 2: λ = 2b/h
    const double b = 0.2, h = 0.6, r = b / h;
    const std::vector<LimitBlock> pair{ground(), box(Vec3(b, 0.4, h), Vec3(-b / 2, 0, h / 2)),
                                       box(Vec3(b, 0.4, h), Vec3(b / 2, 0, h / 2))};
    for (double mu : {1.0, 2.0}) {
        const double lambda = std::min(2 * r, (2 * mu + 1 / mu) / ((mu + 1 / mu) / r - 1));
        INFO("μ = " << mu);
        CHECK(collapse_multiplier(pair, kGravity, push(), mu).lambda == Approx(lambda).epsilon(1e-9));
    }
    // a brick alone tips at b/h: its neighbour only helps
    CHECK(collapse_multiplier({ground(), pair[1]}, kGravity, push(), 2.0).lambda == Approx(r).epsilon(1e-9));
}

TEST_CASE("limit analysis: a stack whose top block sits off centre", "[oracle][limit]") {
    // two 0.4 m cubes, the upper one shifted e = 0.1 m along +x: pushed along +x the top tips about
    // the lower's front edge at (b/2 − e)/(h/2) = 0.5, the pair about the base's front edge at
    // (b/2 − e/2)/h = 0.375; pushed along −x 1 and (b/2 + e/2)/h = 0.625
    const double b = 0.4, e = 0.1;
    const std::vector<LimitBlock> stack{ground(), box(Vec3(b, b, b), Vec3(0, 0, b / 2)),
                                        box(Vec3(b, b, b), Vec3(e, 0, 1.5 * b))};
    CHECK(collapse_multiplier(stack, kGravity, push(), 2.0).lambda ==
          Approx(std::min((b / 2 - e) / (b / 2), (b / 2 - e / 2) / b)).epsilon(1e-9));
    CHECK(collapse_multiplier(stack, kGravity, push(M_PI), 2.0).lambda ==
          Approx(std::min(1.0, (b / 2 + e / 2) / b)).epsilon(1e-9));
    // a narrower top: e = 0.15 and half the height, both mechanisms at 0.5, still the minimum
    const std::vector<LimitBlock> flat{ground(), box(Vec3(b, b, b), Vec3(0, 0, b / 2)),
                                       box(Vec3(b, b, b / 2), Vec3(0.15, 0, 1.25 * b))};
    CHECK(collapse_multiplier(flat, kGravity, push(), 2.0).lambda == Approx(0.5).epsilon(1e-9));
}

TEST_CASE("limit analysis: a running-bond wall pushed along its length", "[oracle][limit]") {
    const auto wall = running_wall();
    // bed joints slide at μ (any course and all above it)
    CHECK(collapse_multiplier(wall, kGravity, push(), 0.6).lambda == Approx(0.6).epsilon(1e-9));
    // for μ between about 0.635 and 1 a wedge at the leading end goes first: the closer of
    // course 2, the end brick of course 3, the end brick and the closer of course 4, their centre
    // of mass at x = z = 17/30 m (the wall spans x ∈ [−0.8, 0.8] from z = 0), turning as one body
    // about a point (ox, oz). In the associative statics a joint's separation must be at least μ
    // times its slip (and the wedge loses no energy in them): λ = (ox − 17/30)/(17/30 − oz),
    // least where the bed under the closer (at its leading corner x = 0.8, z = 0.2) and the
    // closer's head joint (x = 0.6, z = 0.2) both bind: ox = 0.8 + μ(0.2 − oz),
    // oz = 0.2(1 − μ − μ²)/(1 − μ²)
    for (double mu : {0.7, 0.8}) {
        const double oz = 0.2 * (1 - mu - mu * mu) / (1 - mu * mu), ox = 0.8 + mu * (0.2 - oz);
        const double lambda = (ox - 17.0 / 30) / (17.0 / 30 - oz);
        INFO("μ = " << mu);
        const auto r = collapse_multiplier(wall, kGravity, push(), mu);
        CHECK(r.lambda == Approx(lambda).epsilon(1e-9));   // 0.66361 and 0.72603 (53/73)
        CHECK(r.lambda < mu);
        // the wedge alone moves, turning about +y
        int moving = 0;
        for (size_t i = 0; i < wall.size(); ++i)
            if (r.mechanism[i].velocity.norm() > 1e-6) ++moving;
        CHECK(moving == 4);
    }
    // very high friction: the wall turns as one about its leading foot, λ = L/H = 1.6/0.8 (the
    // rear bricks hang on their head joints by friction: associative statics)
    CHECK(collapse_multiplier(wall, kGravity, push(), 5.0).lambda == Approx(2.0).epsilon(1e-9));
}

TEST_CASE("limit analysis: the blocks' order does not matter", "[oracle][limit]") {
    std::mt19937 rng(17);
    for (const auto& [blocks, live, mu] : {std::tuple{pushover_wall(), push(M_PI / 2), 0.8},
                                           std::tuple{running_wall(), push(), 0.8},
                                           std::tuple{arch(21, 0.15, false), push(), 1.0}}) {
        const double lambda = collapse_multiplier(blocks, kGravity, live, mu).lambda;
        auto shuffled = blocks;
        std::shuffle(shuffled.begin(), shuffled.end(), rng);
        // the same programme with its rows and columns permuted: round-off of the pivots only
        CHECK(collapse_multiplier(shuffled, kGravity, live, mu).lambda == Approx(lambda).epsilon(1e-9));
    }
}

TEST_CASE("limit analysis: turning the whole assembly does not matter", "[oracle][limit]") {
    const Quat q = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    for (const auto& [blocks, live, mu] : {std::tuple{pushover_wall(), push(M_PI / 2), 0.8},
                                           std::tuple{running_wall(), push(), 0.8},
                                           std::tuple{arch(21, 0.15, false), push(), 1.0}}) {
        const auto r = collapse_multiplier(blocks, kGravity, live, mu);
        const auto t = turned(blocks, q, live, mu);
        // the corners' round-off under the rotation (1e-16 m) moves no contact: 1e-7
        CHECK(t.interfaces == r.interfaces);
        CHECK(t.lambda == Approx(r.lambda).epsilon(1e-7));
    }
}

TEST_CASE("limit analysis: bad input is refused", "[oracle][limit]") {
    const std::vector<LimitBlock> blocks{ground(), box(Vec3(0.4, 0.4, 0.4), Vec3(0, 0, 0.2))};
    CHECK_THROWS_AS(collapse_multiplier(blocks, kGravity, push(), -0.1), Error);
    auto massless = blocks;
    massless[1].mass = 0.0;
    CHECK_THROWS_AS(collapse_multiplier(massless, kGravity, push(), 0.5), Error);
    // no free block: nothing can fail
    const auto none = collapse_multiplier({ground()}, kGravity, push(), 0.5);
    CHECK(std::isinf(none.lambda));
    CHECK(none.stands_at_zero);
}

TEST_CASE("limit analysis: joints inset from their edges, as compliant contacts hinge", "[oracle][limit]") {
    // a 0.4 × 0.4 × 0.4 m block on the ground, its base inset δ: it tips about a line δ inside
    // its edge, λ = (w/2 − δ)/(h/2)
    const std::vector<LimitBlock> cube{ground(), box(Vec3(0.4, 0.4, 0.4), Vec3(0, 0, 0.2))};
    for (double d : {0.0, 0.001, 0.01, 0.1})
        CHECK(collapse_multiplier(cube, kGravity, push(), 2.0, d).lambda == Approx((0.2 - d) / 0.2).epsilon(1e-9));
    // a base narrower than twice the inset carries its force at its middle: λ = 0
    CHECK(collapse_multiplier(cube, kGravity, push(), 2.0, 0.3).lambda == Approx(0.0).margin(1e-9));
    // the three-drum column: every bed joint inset, the base governs: (B/2 − δ)/(H/2)
    std::vector<LimitBlock> column{ground()};
    for (int i = 0; i < 3; ++i) column.push_back(box(Vec3(0.4, 0.4, 0.5), Vec3(0, 0, 0.25 + 0.5 * i)));
    CHECK(collapse_multiplier(column, kGravity, push(), 2.0, 0.002).lambda == Approx(0.198 / 0.75).epsilon(1e-9));
    // the arch near its least thickness loses far more to the same inset than the column does
    const auto a = arch(21, 0.15, false);
    const double rigid = collapse_multiplier(a, kGravity, push(), 1.0).lambda;
    const double inset = collapse_multiplier(a, kGravity, push(), 1.0, 0.001).lambda;
    INFO("arch: " << rigid << " → " << inset << " with 1 mm");
    CHECK(inset < rigid * 0.98);
    CHECK(inset > 0.0);
}

TEST_CASE("limit analysis: an assembly beyond the blocks it solves within minutes is refused at once", "[oracle][limit]") {
    std::vector<LimitBlock> many{ground()};
    for (long i = 0; i <= kLimitMaxFreeBlocks; ++i) many.push_back(box(Vec3(0.1, 0.1, 0.1), Vec3(0.2 * double(i), 0, 0.05)));
    CHECK_THROWS_WITH(collapse_multiplier(many, kGravity, push(), 0.5), Catch::Contains("2001 free blocks, beyond the 2000"));
}
