// [ground_motion]: a record from a CSV file or inline arrays becomes one inertial body load per
// free block; bad records are refused with file, line, key and value.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "scene_fixture.hpp"

using namespace cairn;
using namespace cairn::test;
using Catch::Matchers::Contains;

TEST_CASE("an inline ground motion gives each free block the load -m a_g(t)", "[scene][ground]") {
    Scene s = parse_scene(with_extra("[ground_motion]\ntime = [0, 1, 2]\nacceleration = [0, 2, 2]\n"
                                     "units = \"m/s2\"\ndirection = [0, 2, 0]\n"),
                          "t.toml");
    REQUIRE(s.ground_motion);
    REQUIRE(s.loads.size() == 1);   // A only: B is fixed (the ground)
    const LoadDef& l = s.loads[0];
    CHECK(l.body);
    CHECK(l.force.isApprox(Vec3(0, -2600.0, 0)));            // −m along the unit direction
    CHECK(l.factor(0.5) == Approx(1.0));                      // linear interpolation, m/s²
    CHECK(l.factor(1.5) == Approx(2.0));
    CHECK(l.factor(2.5) == 0.0);                              // zero after the record
    CHECK(scene_to_json(s)["ground_motion"]["peak_acceleration"] == 2.0);
}

TEST_CASE("the El Centro record loads from CSV in g, relative to the scene file", "[scene][ground]") {
    const std::string dir = std::string(CAIRN_SOURCE_DIR) + "/scenarios/earthquake/";
    Scene s = parse_scene(with_extra("[ground_motion]\nfile = \"../data/elcentro_1940_ns.csv\"\nscale = 0.5\n"),
                          dir + "t.toml");
    const auto& a = s.ground_motion->components.at(0).acceleration;
    // every data row: 0 to 31.18 s at 0.02 s is 1560 samples (the file's comment says 1559)
    REQUIRE(a.time.size() == 1560);
    CHECK(a.time.back() == Approx(31.18));
    CHECK(a.time[1] - a.time[0] == Approx(0.02));
    CHECK(a.value[0] == Approx(0.5 * 9.81 * 0.00630));   // first sample 0.00630 g, scaled by 0.5
}

TEST_CASE("bad ground motions are refused with file, line, key and value", "[scene][ground]") {
    CHECK_THAT(error_of(with_extra("[ground_motion]\nfile = \"nope.csv\"\n")),
               Contains("bad.toml:21: ground_motion.file = \"nope.csv\": cannot open the ground-motion file"));
    CHECK_THAT(error_of(with_extra("[ground_motion]\ntime = [0, 0]\nacceleration = [1, 2]\n")),
               Contains("bad.toml:21: ground_motion.time = [0, 0]: times must increase strictly"));
    CHECK_THAT(error_of(with_extra("[ground_motion]\ntime = [0, 1]\nacceleration = [1, 2]\nunits = \"gal\"\n")),
               Contains("bad.toml:23: ground_motion.units = \"gal\": expected \"g\""));
    CHECK_THAT(error_of(with_extra("[ground_motion]\ntime = [0, 1]\nacceleration = [1]\n")),
               Contains("ground_motion.acceleration"));
    CHECK_THAT(error_of(with_extra("[ground_motion]\nfile = \"x.csv\"\ntime = [0, 1]\n")),
               Contains("not both"));
}

TEST_CASE("a long record in an error is quoted by its start and its length", "[scene][ground]") {
    // 200 times, the second equal to the first: the message names the key and the sample, and
    // quotes the array's start with its element count instead of all 200 numbers
    std::string times = "[0";
    for (int i = 0; i < 199; ++i) times += ", " + std::to_string(0.001 * i);
    times += "]";
    std::string accel = "[0";
    for (int i = 0; i < 199; ++i) accel += ", 1";
    accel += "]";
    const std::string e =
        error_of(with_extra("[ground_motion]\ntime = " + times + "\nacceleration = " + accel + "\n"));
    CHECK_THAT(e, Contains("bad.toml:21: ground_motion.time = [0, 0.000000, 0.001000, "));
    CHECK_THAT(e, Contains(", … (200 elements)]: times must increase strictly"));
    CHECK(e.size() < 300);
}

TEST_CASE("every sample, the first too, is finite after units and scale", "[scene][ground][limits]") {
    const auto dir = std::filesystem::path(CAIRN_BINARY_DIR) / "test_scratch" / "core" / "ground";
    std::filesystem::create_directories(dir);
    // 1e308 g is finite as written and infinite in m/s²: the first sample, after the units
    std::ofstream(dir / "huge.csv") << "t_s,accel_g\n0,1e308\n0.02,0\n";
    const std::string scene = (dir / "t.toml").string();
    std::string msg;
    try {
        parse_scene(with_extra("[ground_motion]\nfile = \"huge.csv\"\n"), scene);
    } catch (const Error& e) {
        msg = e.what();
    }
    CHECK_THAT(msg, Contains("t.toml:21: ground_motion.file = \"huge.csv\": sample 0: acceleration 1e+308 × units 9.81 "
                             "× scale 1 is not finite"));
    // finite samples that overflow with the scale: the scale is named
    CHECK_THAT(error_of(with_extra("[ground_motion]\ntime = [0, 1]\nacceleration = [1e300, 1]\nunits = \"m/s2\"\n"
                                   "scale = 1e10\n")),
               Contains("bad.toml:24: ground_motion.scale = 1e10: sample 0: acceleration 1e+300 × units 1 × scale "
                        "1e+10 is not finite"));
    // a non-finite first time is refused as well
    std::ofstream(dir / "badtime.csv") << "t_s,accel_g\n1e400,0\n0.02,0\n";
    try {
        parse_scene(with_extra("[ground_motion]\nfile = \"badtime.csv\"\n"), scene);
        msg.clear();
    } catch (const Error& e) {
        msg = e.what();
    }
    CHECK_THAT(msg, Contains("ground_motion.file = \"badtime.csv\": ") && Contains("(sample 0"));
}

TEST_CASE("per-axis records give one load per free block and axis, with a common scale", "[scene][ground]") {
    Scene s = parse_scene(with_extra("[ground_motion]\nscale = 2\nstart = 0.5\n"
                                     "[ground_motion.x]\ntime = [0, 1]\nacceleration = [1, 1]\nunits = \"m/s2\"\n"
                                     "[ground_motion.z]\ntime = [0, 1]\nacceleration = [0.1, 0.3]\nunits = \"g\"\nscale = 0.5\n"),
                          "t.toml");
    REQUIRE(s.ground_motion);
    REQUIRE(s.ground_motion->components.size() == 2);
    CHECK(s.ground_motion->components[1].direction == Vec3::UnitZ());
    REQUIRE(s.loads.size() == 2);   // A along x, A along z
    CHECK(s.loads[0].force.isApprox(Vec3(-2600.0, 0, 0)));
    CHECK(s.loads[1].force.isApprox(Vec3(0, 0, -2600.0)));
    CHECK(s.loads[0].factor(0.4) == 0.0);                      // before start
    CHECK(s.loads[0].factor(1.0) == Approx(2.0));              // 1 m/s² × 2
    // z: 0.2 g at the record's 0.5 s, × 2 × 0.5
    CHECK(s.loads[1].factor(1.0) == Approx(0.2 * 9.81));
    CHECK(scene_to_json(s)["ground_motion"]["components"].size() == 2);
}

TEST_CASE("a record at the top and per axis together are refused", "[scene][ground]") {
    CHECK_THAT(error_of(with_extra("[ground_motion]\ntime = [0, 1]\n[ground_motion.y]\ntime = [0, 1]\nacceleration = [0, 1]\n")),
               Contains("bad.toml:21: ground_motion.time = [0, 1]: give one record, or records per axis (x, y, z), not both"));
    CHECK_THAT(error_of(with_extra("[ground_motion]\ndirection = [0, 1, 0]\n[ground_motion.y]\ntime = [0, 1]\nacceleration = [0, 1]\n")),
               Contains("ground_motion.direction"));
    CHECK_THAT(error_of(with_extra("[ground_motion.z]\ntime = [0, 1]\nacceleration = [0, 1]\nunits = \"gal\"\n")),
               Contains("ground_motion.z.units = \"gal\""));
}
