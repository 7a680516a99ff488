// general hexahedra on the reference engines: the face-clipping collider the ODE and MuJoCo backends use,
// a non-box block resting on a base, and the shipped arch of voussoirs
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "engine_scenes.hpp"
#include "common/hexahedron_contact.hpp"
#include "registry.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

Corners shifted(Corners c, const Vec3& by) {
    for (auto& p : c) p += by;
    return c;
}

// a frustum: 1 x 1 m bottom, 0.6 x 0.6 m top, 0.5 m high, bottom face at z = 0
Corners frustum() {
    Corners c;
    for (int i = 0; i < 8; ++i) {
        const double half = kCornerSigns[i][2] < 0 ? 0.5 : 0.3;
        c[i] = Vec3(half * kCornerSigns[i][0], half * kCornerSigns[i][1], kCornerSigns[i][2] < 0 ? 0.0 : 0.5);
    }
    return c;
}

}  // namespace

TEST_CASE("hexahedron contacts: a face on a face gives its four corners", "[engines][hexahedra]") {
    const Corners cube = box_corners(Vec3(1, 1, 1));
    SECTION("overlapping by 1 mm") {
        auto c = hexahedron_contacts(shifted(cube, Vec3(0, 0, 1.0 - 1e-3)), cube);
        REQUIRE(c.size() == 4);
        for (const auto& x : c) {
            CHECK((x.normal - Vec3(0, 0, 1)).norm() < 1e-12);   // pushes the upper block up
            CHECK(x.depth == Approx(1e-3).epsilon(1e-9));
            CHECK(std::abs(std::abs(x.position.x()) - 0.5) < 1e-12);
            CHECK(std::abs(std::abs(x.position.y()) - 0.5) < 1e-12);
        }
    }
    SECTION("exactly touching: four points of zero depth with a unit normal") {
        auto c = hexahedron_contacts(shifted(cube, Vec3(0, 0, 1.0)), cube);
        REQUIRE(c.size() == 4);
        for (const auto& x : c) CHECK(x.normal.norm() == Approx(1.0));
    }
    SECTION("1 mm apart: none") { CHECK(hexahedron_contacts(shifted(cube, Vec3(0, 0, 1.001)), cube).empty()); }
    SECTION("offset by half a block: the overlap's corners") {
        auto c = hexahedron_contacts(shifted(cube, Vec3(0.5, 0, 1.0 - 1e-3)), cube);
        REQUIRE(c.size() == 4);
        for (const auto& x : c) CHECK((x.position.x() == Approx(0.0).margin(1e-12) || x.position.x() == Approx(0.5)));
    }
}

TEST_CASE("hexahedron contacts: the joint of two arch voussoirs", "[engines][hexahedra]") {
    Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/structures/arch.toml", {});
    const Corners& v4 = s.blocks[3].corners;
    const Corners& v5 = s.blocks[4].corners;
    // V4's joint face with V5 is its xi = +1 face (corners 1, 2, 6, 5); push V4 0.1 mm into V5
    const Vec3 joint = (v4[2] - v4[1]).cross(v4[5] - v4[1]).normalized();
    const Vec3 into = joint.dot(v5[0] - v4[0]) > 0 ? joint : Vec3(-joint);
    auto c = hexahedron_contacts(shifted(v4, 1e-4 * into), v5);
    REQUIRE(c.size() == 4);
    for (const auto& x : c) {
        CHECK((x.normal + into).norm() < 1e-9);   // pushes V4 back out of V5
        CHECK(x.depth == Approx(1e-4).epsilon(1e-6));
    }
}

TEST_CASE("reference engines: a frustum rests on a fixed block", "[engines][hexahedra]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    CAPTURE(engine);
    Scene s = base_scene("frustum");
    add_box(s, "base", Vec3(2, 2, 1), Vec3(0, 0, -0.5), true);
    BlockDef f = s.blocks[0];
    f.name = "A";
    f.fixed = false;
    f.shape = Shape::hexahedron;
    f.corners = frustum();
    f.position = Vec3::Zero();
    s.blocks.insert(s.blocks.begin(), f);
    const double com_z = mass_properties(frustum(), 2600.0).centre.z();
    auto b = make_backend(engine);
    b->build(s, RunOptions{});
    const long long steps = std::llround(0.3 / b->time_step());
    for (long long i = 0; i < steps; ++i)
        if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
    Sample end = b->sample();
    CAPTURE(end.blocks[0].position.transpose(), com_z);
    // near-rigid contact: at most 1 mm of penetration, no drift, at rest
    CHECK(std::abs(end.blocks[0].position.z() - com_z) < 1e-3);
    CHECK(end.blocks[0].position.head<2>().norm() < 1e-4);
    CHECK(end.blocks[0].velocity.norm() < 1e-3);
}

TEST_CASE("reference engines: the shipped arch of voussoirs stands", "[engines][hexahedra]") {
    const std::string engine = GENERATE(from_range(engine_names()));
    CAPTURE(engine);
    Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/structures/arch.toml", {});
    auto b = make_backend(engine);
    b->build(s, RunOptions{});
    const Sample start = b->sample();
    double crown_drop = 0.0;
    const long long steps = std::llround(0.5 / b->time_step());
    for (long long i = 0; i < steps; ++i) {
        if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
        crown_drop = std::max(crown_drop, start.probes[0].z() - b->sample().probes[0].z());
    }
    CAPTURE(crown_drop);
    // rigid joints do not close elastically; a joint held at a single point hinges and let the
    // crown sink 1.7 mm in 0.5 s (ODE's own convex collider; MuJoCo's mesh collider about 10 mm),
    // so 0.1 mm separates the two (MuJoCo's soft contact creeps about 0.04 mm in 0.5 s)
    CHECK(crown_drop < 1e-4);
}
