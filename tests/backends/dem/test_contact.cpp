// Contact forces of a cube pressed a uniform depth into a larger fixed base, against the closed
// forms of a bed of penalty springs: force kn·A·d, stored energy ½·kn·A·d², on either scheme.
#include <catch2/catch.hpp>

#include "dem/block_builder.hpp"
#include "dem/contact.hpp"
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
