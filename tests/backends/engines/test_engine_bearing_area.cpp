// the face that bears a matched contact (backends/common/rigid_blocks): the face most aligned with
// the contact normal pointing out of the block, in its current orientation; ties take the smaller
#include <catch2/catch.hpp>

#include <cmath>

#include "engine_scenes.hpp"
#include "common/rigid_blocks.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

// block 0 of a scene holding a brick 0.4 x 0.2 x 0.2 m, or a frustum of it (top 0.2 x 0.2)
RigidBlock brick(bool frustum) {
    Scene s = base_scene("brick");
    add_box(s, "A", Vec3(0.4, 0.2, 0.2), Vec3::Zero(), false);
    if (frustum) {
        s.blocks[0].shape = Shape::hexahedron;
        for (Vec3& c : s.blocks[0].corners)
            if (c.z() > 0) c.x() *= 0.5;
    }
    return rigid_blocks(s, "test")[0];
}

}  // namespace

TEST_CASE("bearing area: the face whose outward normal is most aligned with the contact's", "[engines][matched]") {
    const RigidBlock b = brick(false);
    const Quat id = Quat::Identity();
    // areas are exact products of the edges (planar rectangles): 1e-12 relative
    CHECK(bearing_area(b, id, Vec3(0, 0, -1)) == Approx(0.08).epsilon(1e-12));   // bed face
    CHECK(bearing_area(b, id, Vec3(1, 0, 0)) == Approx(0.04).epsilon(1e-12));    // end (head joint)
    CHECK(bearing_area(b, id, Vec3(0, -1, 0)) == Approx(0.08).epsilon(1e-12));   // side
    // tilted 10 degrees off the bed face's normal, still the bed face
    CHECK(bearing_area(b, id, Vec3(std::sin(0.17), 0, -std::cos(0.17))) == Approx(0.08).epsilon(1e-12));
    // turned 90 degrees about y: the end now faces down
    const Quat up(Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()));
    CHECK(bearing_area(b, up, Vec3(0, 0, -1)) == Approx(0.04).epsilon(1e-12));
    // exactly between the bed face and the end (an edge-to-edge contact): a tie, the smaller counts
    CHECK(bearing_area(b, id, Vec3(1, 0, -1).normalized()) == Approx(0.04).epsilon(1e-12));
}

TEST_CASE("bearing area: the side of the normal picks the face, not its opposite", "[engines][matched]") {
    // the frustum's bottom (0.08 m²) and top (0.04 m²) are opposite faces of different areas
    const RigidBlock f = brick(true);
    const Quat id = Quat::Identity();
    CHECK(bearing_area(f, id, Vec3(0, 0, -1)) == Approx(0.08).epsilon(1e-12));
    CHECK(bearing_area(f, id, Vec3(0, 0, 1)) == Approx(0.04).epsilon(1e-12));
    // a pair: the frustum on a large fixed block, normal from the frustum (a) down into the block (b)
    Scene s = base_scene("pair");
    add_box(s, "base", Vec3(1, 1, 0.5), Vec3(0, 0, -0.25), true);
    const RigidBlock base = rigid_blocks(s, "test")[0];
    s.contact.damping_rule = ContactDampingRule::none;
    const PointSpring down = matched_point_spring(s, f, id, base, id, Vec3(0, 0, -1));
    CHECK(down.stiffness == Approx(s.contact.kn * 0.08 / 4).epsilon(1e-12));
    // the same pair touching the other way (the block above the frustum's top)
    const PointSpring over = matched_point_spring(s, f, id, base, id, Vec3(0, 0, 1));
    CHECK(over.stiffness == Approx(s.contact.kn * 0.04 / 4).epsilon(1e-12));
}
