// Contact forces of a cube pressed a uniform depth into a larger fixed base, against the closed
// forms of a bed of penalty springs: force kn·A·d, stored energy ½·kn·A·d², on either scheme.
#include <catch2/catch.hpp>

#include "dem/block_builder.hpp"
#include "dem/contact.hpp"
#include "dem/face.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

constexpr double kEdge = 0.5;   // m, the cube's edge (the base is 1 m wide: the cube's face is the hitting one)
constexpr double kDepth = 1e-4; // m, uniform penetration
constexpr double kKn = 3e7;     // N/m³

// the cube pressed kDepth into the base: the cube's total node force and the stored energy
std::pair<Vec3, double> pressed(ContactScheme scheme) {
    Scene s = test::stone_scene();
    s.contact.scheme = scheme;
    s.contact.kn = kKn;
    s.contact.grid_spacing = 0.1;
    add_box(s, "A", Vec3(kEdge, kEdge, kEdge), Vec3(0, 0, 0.5 * kEdge - kDepth), false);
    add_box(s, "base", Vec3(1, 1, 0.5), Vec3(0, 0, -0.25), true);
    std::vector<dem::Block> blocks{dem::make_block(s.blocks[0], s), dem::make_block(s.blocks[1], s)};
    for (auto& b : blocks)
        for (auto& f : b.f) f.setZero();
    dem::ContactSet contacts;
    contacts.configure(s.contact, 0.05 * kEdge);
    contacts.refresh(blocks);
    const auto totals = contacts.apply(blocks, 1e-5);
    Vec3 force = Vec3::Zero();
    for (const auto& f : blocks[0].f) force += f;
    return {force, totals.stored};
}

}  // namespace

TEST_CASE("dem contact: a uniform penetration gives kn·A·d and stores half kn·A·d²", "[dem][contact]") {
    const double area = kEdge * kEdge;
    for (auto scheme : {ContactScheme::paper, ContactScheme::overlap}) {
        const auto [force, stored] = pressed(scheme);
        // the hitting points' areas (paper) and the sub-cells (overlap) sum to the face area, and
        // the depth is the same everywhere: exact but for round-off (the depth is a difference of
        // positions of order 1 m, ~1e-12 of it; 1e-9 leaves room for the sums over the points)
        CHECK(force.z() == Approx(kKn * area * kDepth).epsilon(1e-9));
        CHECK(std::abs(force.x()) + std::abs(force.y()) < 1e-9 * kKn * area * kDepth);   // no shear at rest
        CHECK(stored == Approx(0.5 * kKn * area * kDepth * kDepth).epsilon(1e-9));
    }
}

TEST_CASE("dem blocks: a box is told from other hexahedra", "[dem][contact]") {
    Scene s = test::stone_scene();
    const Quat turned(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    add_box(s, "box", Vec3(0.4, 0.2, 0.3), Vec3(1, 2, 3), false, turned);
    BlockDef wedge = s.blocks[0];   // a voussoir-like trapezoid: its top narrower than its bottom
    wedge.name = "wedge";
    wedge.shape = Shape::hexahedron;
    wedge.corners = box_corners(Vec3(0.4, 0.2, 0.3));
    for (int i = 4; i < 8; ++i) wedge.corners[size_t(i)].x() *= 0.8;
    BlockDef sheared = wedge;   // a parallelepiped: every side planar, not square to its neighbours
    sheared.name = "sheared";
    sheared.corners = box_corners(Vec3(0.4, 0.2, 0.3));
    for (int i = 4; i < 8; ++i) sheared.corners[size_t(i)].x() += 0.05;
    CHECK(dem::make_block(s.blocks[0], s).box);
    CHECK_FALSE(dem::make_block(wedge, s).box);
    CHECK_FALSE(dem::make_block(sheared, s).box);
    s.blocks[0].model = BlockModel::deformable;   // its faces bulge: never a box
    CHECK_FALSE(dem::make_block(s.blocks[0], s).box);
}

TEST_CASE("dem blocks: a rigid block's side frames turn with its nodes, to rounding", "[dem][contact]") {
    // the frames come from the block-frame sides turned by the pose; the nodes by the same pose:
    // the quad of each side's nodes gives the same normal and centre to a few roundings. The
    // nodes lie 8 m from the origin, where one rounding is 8.9e-16 m: the centre is good to a few
    // (1e-14 m), the normal, from differences of nodes over 0.2 m edges, to a few of 4.4e-15
    // (1e-14; 1.7e-15 measured)
    Scene s = test::stone_scene();
    add_box(s, "box", Vec3(0.4, 0.2, 0.3), Vec3(1, 2, 3), false);
    BlockDef wedge = s.blocks[0];
    wedge.name = "wedge";
    wedge.shape = Shape::hexahedron;
    wedge.corners = box_corners(Vec3(0.4, 0.2, 0.3));
    for (int i = 4; i < 8; ++i) wedge.corners[size_t(i)].x() *= 0.8;
    for (const BlockDef& d : {s.blocks[0], wedge}) {
        dem::Block b = dem::make_block(d, s);
        b.body.q = Quat(Eigen::AngleAxisd(2.1, Vec3(-1, 3, 2).normalized()));
        b.body.x = Vec3(-4, 0.5, 7);
        b.update_nodes();
        const dem::SideFrames f = dem::SideFrames::of(b);
        for (int k = 0; k < 6; ++k) {
            const dem::Quad q = b.side_quad(k);
            CHECK((f.normal[size_t(k)] - dem::quad_centre_normal(q)).norm() < 1e-14);
            CHECK((f.centre[size_t(k)] - 0.25 * (q[0] + q[1] + q[2] + q[3])).norm() < 1e-14);
        }
    }
}

TEST_CASE("dem overlap contact: a box target's face is bounded by its neighbours' planes, as by its own edges",
          "[dem][contact]") {
    // The overlap scheme leaves out the edges of a box's whole face: the side constraints hold
    // its neighbours' planes, the same half-spaces. A cube tilted 0.05 rad about two axes, sunk
    // into a fixed block and hanging over two of its edges, pushes on it through those edges: its
    // node forces with and without the shortcut agree to rounding (1e-12 of the total)
    Scene s = test::stone_scene();
    s.contact.scheme = ContactScheme::overlap;
    s.contact.subdivision = 1;
    s.contact.kn = 1e9;
    add_box(s, "cube", Vec3(0.5, 0.5, 0.5), Vec3(0.3, -0.3, 0.25 - 2e-3), false,
            Quat(Eigen::AngleAxisd(0.05, Vec3(1, 1, 0).normalized())));
    add_box(s, "base", Vec3(0.8, 0.8, 0.5), Vec3(0, 0, -0.25), true);
    auto forces = [&](bool shortcut) {
        std::vector<dem::Block> blocks{dem::make_block(s.blocks[0], s), dem::make_block(s.blocks[1], s)};
        REQUIRE(blocks[1].box);
        for (auto& b : blocks) b.box = b.box && shortcut;
        dem::ContactSet contacts;
        contacts.configure(s.contact, 0.05);
        contacts.refresh(blocks);
        const double stored = contacts.apply(blocks, 1e-5).stored;
        return std::make_pair(blocks[0].f, stored);
    };
    const auto [with, stored_with] = forces(true);
    const auto [without, stored_without] = forces(false);
    Vec3 total = Vec3::Zero();
    for (const auto& f : without) total += f;
    REQUIRE(total.z() > 0.0);
    REQUIRE(with.size() == without.size());
    for (size_t i = 0; i < with.size(); ++i) CHECK((with[i] - without[i]).norm() < 1e-12 * total.norm());
    CHECK(stored_with == Approx(stored_without).epsilon(1e-12));
}

TEST_CASE("tie memory: a kept tie names its hitting side, the reverse its target, any other pair nothing", "[dem][contact]") {
    dem::TieMemory m;
    CHECK(m.role(0, 5, 1, 4) == 0);   // empty: the geometric rule decides
    m.kept = {{2, 1, 0, 3}, {0, 5, 1, 4}, {0, 5, 1, 4}, {1, 2, 2, 0}};
    m.index(3);
    REQUIRE(m.kept.size() == 3);   // sorted, each once
    CHECK(m.role(0, 5, 1, 4) == 1);
    CHECK(m.role(1, 4, 0, 5) == -1);
    CHECK(m.role(2, 1, 0, 3) == 1);
    CHECK(m.role(0, 3, 2, 1) == -1);
    CHECK(m.role(0, 4, 1, 4) == 0);   // another side of block 0
    CHECK(m.role(0, 5, 2, 4) == 0);   // another block
    CHECK(m.role(7, 5, 1, 4) == 0);   // a block past the index
}
