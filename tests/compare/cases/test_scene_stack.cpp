// The scene's free blocks read as a centred stack (compare/cases/scene_stack.hpp): what the compare
// report's estimate of the joints' compliance applies to, and what it refuses.
#include <catch2/catch.hpp>

#include <cmath>

#include "cases/case_kind.hpp"
#include "cases/scene_stack.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// three drums 0.4 × 0.4 × 0.5 m on a 2 m slab, shaken along `direction`
Scene column(const Vec3& direction = Vec3::UnitX()) {
    Scene s = test::stone_scene(0.8);
    for (int i = 0; i < 3; ++i) test::add_box(s, "D" + std::to_string(i), Vec3(0.4, 0.4, 0.5), Vec3(0, 0, 0.25 + 0.5 * i), false);
    test::add_box(s, "G", Vec3(2, 2, 0.5), Vec3(0, 0, -0.25), true);
    GroundMotion g;
    GroundComponent c;
    c.direction = direction;
    c.acceleration.time = {0.0, 10.0};   // s: a ramp to 0.5 g
    c.acceleration.value = {0.0, 4.905};
    g.components.push_back(c);
    s.ground_motion = g;
    return s;
}

/// a course of two bricks 0.4 long (x) × 0.2 thick (y) × 0.2 high on the column's slab
Scene course(const Vec3& direction) {
    Scene s = column(direction);
    s.blocks.erase(s.blocks.begin(), s.blocks.begin() + 3);
    test::add_box(s, "L", Vec3(0.4, 0.2, 0.2), Vec3(-0.2, 0, 0.1), false);
    test::add_box(s, "R", Vec3(0.4, 0.2, 0.2), Vec3(0.2, 0, 0.1), false);
    return s;
}

}  // namespace

TEST_CASE("scene stack: a centred column on its base is a stack of its drums", "[compare][stack]") {
    const auto stack = cases::centred_stack(column());
    REQUIRE(stack);
    REQUIRE(stack->layers.size() == 3);
    CHECK(stack->rigid_multiplier() == Approx(0.4 / 1.5));   // B/H about the base edge
    CHECK(stack->layers[1].mass == Approx(2600 * 0.4 * 0.4 * 0.5));
}

TEST_CASE("scene stack: what is not a centred stack under one horizontal record is refused", "[compare][stack]") {
    SECTION("no ground motion") {
        Scene s = column();
        s.ground_motion.reset();
        CHECK_FALSE(cases::centred_stack(s));
    }
    SECTION("a vertical record") { CHECK_FALSE(cases::centred_stack(column(Vec3::UnitZ()))); }
    SECTION("a drum set off the axis by 5 % of the width") {
        Scene s = column();
        s.blocks[1].position.x() += 0.02;
        CHECK_FALSE(cases::centred_stack(s));
    }
    SECTION("a drum lifted off the one below") {
        Scene s = column();
        s.blocks[2].position.z() += 0.01;
        CHECK_FALSE(cases::centred_stack(s));
    }
    SECTION("no fixed block under the first drum") {
        Scene s = column();
        s.blocks[3].position.z() -= 0.1;
        CHECK_FALSE(cases::centred_stack(s));
    }
    SECTION("a course with a gap") {
        Scene s = course(Vec3::UnitY());
        s.blocks[1].position.x() -= 0.05;   // the left brick 5 cm off the right one
        CHECK_FALSE(cases::centred_stack(s));
    }
}

TEST_CASE("scene stack: a course of bricks is a layer pushed out of its plane, not in it", "[compare][stack]") {
    const auto out_of_plane = cases::centred_stack(course(Vec3::UnitY()));
    REQUIRE(out_of_plane);
    CHECK(out_of_plane->layers.size() == 1);
    CHECK(out_of_plane->rigid_multiplier() == Approx(0.2 / 0.2));   // t/H of the one course
    CHECK_FALSE(cases::centred_stack(course(Vec3::UnitX())));
}

TEST_CASE("scene stack: a column shaken at an angle to its faces tips over a corner", "[compare][stack]") {
    // 30° from x: the resultant's offset λ·H·(cos 30°, sin 30°) reaches the side x = B/2 first,
    // at λ = (B/2)/(H·cos 30°) = 0.2/(0.75·0.8660)
    const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
    const auto oblique = cases::centred_stack(column(Vec3(c, s, 0)));
    REQUIRE(oblique);
    CHECK(oblique->push_angle == Approx(kPi / 6));
    CHECK(oblique->rigid_multiplier() == Approx(0.2 / (0.75 * c)));
    // the same column and slab turned 30° about the vertical and shaken along their x axis: the
    // push is along the drums' faces again
    Scene turned = column(Vec3(c, s, 0));
    for (auto& b : turned.blocks) {
        b.orientation = Quat(Eigen::AngleAxisd(kPi / 6, Vec3::UnitZ()));
        b.position = b.orientation * b.position;
    }
    const auto along = cases::centred_stack(turned);
    REQUIRE(along);
    CHECK(std::abs(std::sin(along->push_angle)) < 1e-9);
    CHECK(along->rigid_multiplier() == Approx(0.4 / 1.5));
    // refused: a course of bricks shaken at an angle to its plane, and a column whose slab does not
    // run past its first drum across the push (it would tip over the slab's edge)
    CHECK_FALSE(cases::centred_stack(course(Vec3(s, c, 0))));
    auto narrow = [](const Vec3& direction) {
        Scene n = column(direction);
        n.blocks[3].corners = box_corners(Vec3(2, 0.4, 0.5));   // 2 m along x, as wide as the drums across
        return n;
    };
    CHECK_FALSE(cases::centred_stack(narrow(Vec3(c, s, 0))));
    CHECK(cases::centred_stack(narrow(Vec3::UnitX())));   // pushed along x it runs past the drum
}

TEST_CASE("pushover reference: a scene neither the stack oracle nor the limit analysis models is refused before any "
          "run, naming the key",
          "[compare][stack]") {
    const cases::CaseKind& kind = cases::case_kind("pushover", "test");
    auto refusal = [&](const Scene& s) {
        try {
            kind.check(s);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    CHECK(refusal(column()).empty());                 // a centred column pushed along a side: the stack
    CHECK(refusal(course(Vec3::UnitY())).empty());    // a course pushed out of its plane: the stack
    // read as an assembly: a drum off the axis, a push at an angle
    Scene off = column();
    off.blocks[1].position.x() += 0.02;
    CHECK(refusal(off).empty());
    const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
    CHECK(refusal(column(Vec3(c, s, 0))).empty());
    // in its plane the course slides at λ = μ = 0.8 before either brick tips (b/h = 2): read as an
    // assembly, shown and not judged (test_assembly_pushover.cpp)
    CHECK(refusal(course(Vec3::UnitX())).empty());
    CHECK_THAT(refusal(column(Vec3::UnitZ())), Catch::Contains("ground_motion.direction must be horizontal"));
    Scene floating = column();
    floating.blocks[3].position.z() -= 0.1;
    CHECK_THAT(refusal(floating), Catch::Contains("no statically admissible state under gravity"));
    Scene pushed = column();
    LoadDef extra;
    extra.block = 2;
    extra.force = Vec3(10, 0, 0);
    pushed.loads.push_back(extra);
    CHECK_THAT(refusal(pushed), Catch::Contains("[loads]: a load on block 'D2'"));
}

TEST_CASE("scene stack: a column written to six digits is still a stack pushed along its side", "[compare][stack]") {
    // positions and the record's direction as a user types them from a turned scene: the drums
    // 3 µm apart and the push 1e-6 rad off their faces (before, a gap above 1e-6 of the height or
    // an angle above 1e-9 rad read it as an assembly, and dem lost its Winkler stack oracle)
    Scene s = column(Vec3(1.0, 1e-6, 0.0).normalized());
    s.blocks[1].position.z() += 3e-6;
    s.blocks[2].position.z() += 6e-6;
    const auto stack = cases::centred_stack(s);
    REQUIRE(stack);
    CHECK(stack->layers.size() == 3);
    CHECK(std::abs(stack->push_angle) < 1e-5);
    CHECK(stack->rigid_multiplier() == Approx(0.4 / 1.5).epsilon(1e-4));
    // a gap of 1 mm on a 0.5 m drum (2e-3 of it) is a gap: refused
    s.blocks[2].position.z() += 1e-3;
    CHECK_FALSE(cases::centred_stack(s));
}
