// a valid scene lands in the right fields: values, defaults, pivot folding, JSON export

#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/hexahedron.hpp"
#include "scene/scene_io.hpp"
#include "scene_fixture.hpp"

using namespace cairn;

TEST_CASE("the base scene takes every default", "[scene]") {
    Scene s = parse_scene(test::kBaseScene, "dir/base.toml");
    CHECK(s.name == "t");
    CHECK(s.source == "dir/base.toml");
    CHECK(s.gravity == Vec3(0, 0, -9.81));
    CHECK(s.run.duration == 0.5);
    CHECK_FALSE(s.run.dt.has_value());
    CHECK(s.run.dt_safety == 0.1);
    CHECK(s.run.output_interval == 1e-3);
    CHECK(s.run.contact_interval == 10);
    CHECK_FALSE(s.run.contact_margin.has_value());
    CHECK(s.run.settle);
    REQUIRE(s.materials.size() == 1);
    CHECK(s.materials[0].young == 30e9);
    CHECK(s.contact.ks == s.contact.kn);   // ks defaults to kn
    CHECK(s.contact.damping_rule == ContactDampingRule::none);
    CHECK(s.contact.restitution == 0.0);
    CHECK(s.contact.grid_spacing == 0.1);
    CHECK(s.damping.alpha == 0.0);
    CHECK(s.damping.beta == 0.0);
    REQUIRE(s.blocks.size() == 2);
    CHECK(s.blocks[0].name == "A");   // name order
    CHECK(s.blocks[1].name == "B");
    CHECK(s.blocks[1].fixed);
    CHECK(s.blocks[0].model == BlockModel::rigid);
    CHECK(s.blocks[0].orientation.coeffs() == Quat::Identity().coeffs());
    CHECK(s.blocks[0].corners[6] == Vec3(0.5, 0.5, 0.5));   // box_corners(size)
    CHECK(s.block_index("B") == 1);
    CHECK(s.block_index("C") == -1);
    CHECK_FALSE(s.reference.has_value());
    CHECK(s.backend_settings.empty());
}

TEST_CASE("the name defaults to the file stem", "[scene]") {
    Scene s = parse_scene(test::with_line(1, ""), "scenarios/paper/stability.toml");
    CHECK(s.name == "stability");
}

TEST_CASE("every section's values land in their fields", "[scene]") {
    Scene s = parse_scene(R"(
gravity = [0, 0, -10]
description = "all keys"
[run]
duration = 2
dt = 1e-5
dt_safety = 0.5
output_interval = 0.01
contact_interval = 3
contact_margin = 0.002
settle = false
[materials.stone]
density = 2600
young = 30e9
poisson = 0.2
[materials.soft]
density = 1000
young = 1e6
poisson = -0.5
[contact]
kn = 3e7
ks = 1e7
friction = 0.4
damping_time = 0.002
restitution = 0.5
scheme = "paper"
grid_spacing = 0.05
[damping]
alpha = 1.5
beta = 1e-4
[blocks.W]
shape = "hexahedron"
corners = [[0,0,0],[2,0,0],[2,1,0],[0,1,0],[0,0,1],[2,0,1],[2,1,1],[0,1,1]]
material = "soft"
velocity = [1, 2, 3]
angular_velocity = [0, 0, 4]
orientation = {quaternion = [0, 0, 0, 1]}
model = "deformable"
[blocks.W.mesh]
divisions = [2, 1, 1]
mass = "consistent"
fix_base = true
fixed_nodes = [0, 11]
[blocks.Base]
size = [4, 4, 1]
position = [0, 0, -0.5]   # under W, which stands on z = 0 (blocks must not overlap at t = 0)
material = "stone"
fixed = true
[loads.push]
block = "W"
force = [100, 0, 0]
ramp = 0.2
start = 0.1
[loads.twist]
block = "W"
force = [0, 10, 0]
corner = 6
[probes.tip]
block = "W"
corner = 5
[probes.mid]
block = "Base"
point = [0.1, 0.2, 0.3]
[reference]
kind = "housner"
block = "W"
theta0 = 0.5
axis_y = 1
[backends.bullet]
iterations = 50
erp = 0.2
split = true
solver = "pgs"
)",
                          "all.toml");
    CHECK(s.description == "all keys");
    CHECK(s.gravity == Vec3(0, 0, -10));
    CHECK(*s.run.dt == 1e-5);
    CHECK(s.run.dt_safety == 0.5);
    CHECK(s.run.output_interval == 0.01);
    CHECK(s.run.contact_interval == 3);
    CHECK(*s.run.contact_margin == 0.002);
    CHECK_FALSE(s.run.settle);
    REQUIRE(s.materials.size() == 2);   // name order: soft, stone
    CHECK(s.materials[0].name == "soft");
    CHECK(s.materials[0].poisson == -0.5);
    CHECK(s.contact.ks == 1e7);
    CHECK(s.contact.friction == 0.4);
    CHECK(s.contact.damping_rule == ContactDampingRule::time);
    CHECK(s.contact.damping == 0.002);
    CHECK(s.contact.restitution == 0.5);
    CHECK(s.contact.grid_spacing == 0.05);
    CHECK(s.contact.scheme == ContactScheme::paper);
    CHECK(s.damping.alpha == 1.5);
    CHECK(s.damping.beta == 1e-4);
    REQUIRE(s.blocks.size() == 2);
    const BlockDef& w = s.blocks[1];   // "Base" < "W"
    CHECK(w.name == "W");
    CHECK(w.shape == Shape::hexahedron);
    CHECK(w.corners[1] == Vec3(2, 0, 0));
    CHECK(w.material == 0);
    CHECK(w.velocity == Vec3(1, 2, 3));
    CHECK(w.angular_velocity == Vec3(0, 0, 4));
    CHECK(w.orientation.z() == 1.0);
    CHECK(w.model == BlockModel::deformable);
    CHECK(w.mesh.divisions == std::array<int, 3>{2, 1, 1});
    CHECK(w.mesh.mass == MassScheme::consistent);
    CHECK(w.mesh.fix_base);
    CHECK(w.mesh.fixed_nodes == std::vector<int>{0, 11});
    REQUIRE(s.loads.size() == 2);   // name order: push, twist
    CHECK(s.loads[0].block == 1);
    CHECK(s.loads[0].point.isApprox(Vec3(1, 0.5, 0.5)));   // default: the centre of mass
    CHECK(s.loads[0].ramp == 0.2);
    CHECK(s.loads[0].start == 0.1);
    CHECK(s.loads[1].point == Vec3(2, 1, 1));   // corner 6
    REQUIRE(s.probes.size() == 2);   // name order: mid, tip
    CHECK(s.probes[0].name == "mid");
    CHECK(s.probes[0].block == 0);
    CHECK(s.probes[0].point == Vec3(0.1, 0.2, 0.3));
    CHECK(s.probes[1].point == Vec3(2, 0, 1));   // corner 5
    REQUIRE(s.reference.has_value());
    CHECK(s.reference->kind == "housner");
    CHECK(s.reference->block == 1);
    CHECK(s.reference->values.at("theta0") == 0.5);
    CHECK(s.reference->values.at("axis_y") == 1.0);
    const auto& bullet = s.backend_settings.at("bullet");
    CHECK(std::get<long long>(bullet.at("iterations").value) == 50);
    CHECK(bullet.at("iterations").origin == "all.toml:70");
    CHECK(std::get<double>(bullet.at("erp").value) == 0.2);
    CHECK(std::get<bool>(bullet.at("split").value));
    CHECK(std::get<std::string>(bullet.at("solver").value) == "pgs");
}

TEST_CASE("a pivot folds into the position: the block turns about that world point",
          "[scene]") {
    Scene s = parse_scene(test::with_line(13, "position = [0, 0, 0.5]\n"
                                              "orientation = {axis = [0, 2, 0], angle = 0.5}\n"
                                              "pivot = [0.5, 0, 0]"),
                          "pivot.toml");
    const BlockDef& a = s.blocks[0];
    // the pivot is the +x bottom edge of A: it stays where it was
    Vec3 edge_local(0.5, 0, -0.5);
    Vec3 edge_world = a.position + a.orientation * edge_local;
    CHECK((edge_world - Vec3(0.5, 0, 0)).norm() < 1e-12);
    // the axis was normalised and the angle kept
    Eigen::AngleAxisd aa(a.orientation);
    CHECK(aa.angle() == Approx(0.5).epsilon(1e-12));
    CHECK((aa.axis() - Vec3(0, 1, 0)).norm() < 1e-12);
    // the centre moved along the circle about the pivot
    CHECK((a.position - Vec3(0.5, 0, 0)).norm() == Approx(std::hypot(0.5, 0.5)).epsilon(1e-12));
}

TEST_CASE("a contact damping of 0 is no contact damping, by ratio or by time", "[scene]") {
    // a reference judges rigid-contact engines only on undamped scenes (Housner's impact), and the
    // report names damping an engine cannot represent: both read the rule, which must say none
    for (const std::string key : {"damping_ratio = 0.0", "damping_time = 0", "damping_ratio = 0.0\n# same"}) {
        const Scene s = parse_scene(test::with_line(10, "friction = 0.6\n" + key), "z.toml");
        CHECK(s.contact.damping_rule == ContactDampingRule::none);
        CHECK(s.contact.damping == 0.0);
    }
    const Scene damped = parse_scene(test::with_line(10, "friction = 0.6\ndamping_ratio = 1e-9"), "z.toml");
    CHECK(damped.contact.damping_rule == ContactDampingRule::ratio);
    // an override to 0 as well
    const Scene set = parse_scene(test::with_line(10, "friction = 0.6\ndamping_ratio = 0.05"), "z.toml",
                                  {Override{"contact.damping_ratio", "0"}});
    CHECK(set.contact.damping_rule == ContactDampingRule::none);
}

TEST_CASE("a box load without a point acts at the centre of mass", "[scene]") {
    Scene s = parse_scene(test::with_extra("[loads.h]\nblock = \"A\"\nforce = [1, 0, 0]\n"
                                           "point = \"centre\"\n"),
                          "c.toml");
    CHECK(s.loads[0].point.norm() < 1e-12);
}

TEST_CASE("scene_to_json records every parameter", "[scene]") {
    Scene s = parse_scene(test::with_extra("[reference]\nkind = \"rest\"\nblock = \"A\"\n"
                                           "[backends.dem]\nx = 1.5\n"),
                          "j.toml");
    nlohmann::json j = scene_to_json(s);
    CHECK(j["name"] == "t");
    CHECK(j["run"]["dt"] == "auto");
    CHECK(j["run"]["duration"] == 0.5);
    CHECK(j["contact"]["damping_rule"] == "none");
    CHECK(j["contact"]["ks"] == 3e7);
    CHECK(j["blocks"].size() == 2);
    CHECK(j["blocks"][0]["orientation"] == nlohmann::json({1.0, 0.0, 0.0, 0.0}));
    CHECK(j["blocks"][0]["corners"].size() == 8);
    CHECK(j["blocks"][0]["material"] == "stone");
    CHECK(j["blocks"][1]["fixed"] == true);
    CHECK(j["materials"][0]["density"] == 2600.0);
    CHECK(j["reference"]["kind"] == "rest");
    CHECK(j["reference"]["block"] == "A");
    CHECK(j["backends"]["dem"]["x"]["value"] == 1.5);
    CHECK(j["gravity"] == nlohmann::json({0.0, 0.0, -9.81}));
}
