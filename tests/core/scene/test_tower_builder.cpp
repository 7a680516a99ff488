// the bonded tower and the house: brick counts, no overlap by the loader's check and by brute
// force, mass and centre of mass in closed form, the corner bond and the openings' lintels
#include <catch2/catch.hpp>

#include "builder_checks.hpp"
#include "error.hpp"
#include "scene/house_builder.hpp"

using namespace cairn;

TEST_CASE("a bonded tower: counts, no overlap, mass, centre of mass", "[scene][builders]") {
    TowerSpec t{5, 4, 6, 0.24, 0.07, {}};
    Scene s = test::builder_scene();
    add_tower(s, t);
    // per course 2·5 + 2·4 − 2 bricks: the through walls hold 5 or 4 bricks, the others one less
    CHECK(tower_brick_count(t) == 6 * 16);
    CHECK(s.blocks.size() == size_t(1 + 6 * 16));
    const Scene loaded = test::reloaded(s);
    CHECK(test::deepest_overlap(loaded) < 1e-9);
    const auto m = test::free_mass(loaded);
    CHECK(m.mass == Approx(2000.0 * 6 * 16 * 0.24 * 0.12 * 0.07).epsilon(1e-9));
    CHECK(m.centre.x() == Approx(0.0).margin(1e-9));
    CHECK(m.centre.y() == Approx(0.0).margin(1e-9));
    CHECK(m.centre.z() == Approx(3 * 0.07).epsilon(1e-9));
    // corner bond: on even courses wall 0 runs through the corner (x from −Lx/2), on odd ones it
    // starts half a brick in, behind wall 3
    auto first_x = [&](int c) {
        double x = 1e9;
        const std::string prefix = "c00" + std::to_string(c) + "_w0_";
        for (const BlockDef& b : s.blocks)
            if (b.name.rfind(prefix, 0) == 0) x = std::min(x, b.position.x() - 0.5 * b.size.x());
        return x;
    };
    CHECK(first_x(0) == Approx(-0.6).margin(1e-12));
    CHECK(first_x(1) == Approx(-0.48).margin(1e-12));
}

TEST_CASE("a tower of 10^4 bricks loads", "[scene][builders]") {
    TowerSpec t{13, 13, 200, 0.24, 0.07, {}};
    Scene s = test::builder_scene();
    add_tower(s, t);
    CHECK(tower_brick_count(t) == 10000);
    const Scene loaded = test::reloaded(s);   // the loader's limits (16 MiB, overlaps) let it through
    CHECK(loaded.blocks.size() == 10001u);
}

namespace {
// a house of 10 × 8 bricks and 20 courses, with a door of 14 courses and windows of courses 6-12
HouseSpec small_house() {
    HouseSpec h;
    h.walls = TowerSpec{10, 8, 20, 0.24, 0.07, {}};
    h.door_width = 0.72;
    h.door_height = 0.98;    // 14 courses
    h.window_width = 0.48;
    h.window_sill = 0.42;    // course 6
    h.window_height = 0.49;  // up to course 13
    return h;
}
}  // namespace

TEST_CASE("a house: openings remove their volume, lintels bridge them", "[scene][builders]") {
    HouseSpec h = small_house();
    const auto openings = house_openings(h);
    REQUIRE(openings.size() == 4u);
    CHECK(openings[0].course_to == 14);
    CHECK(openings[1].course_from == 6);
    CHECK(openings[1].course_to == 13);
    Scene s = test::builder_scene();
    add_house(s, h);
    const Scene loaded = test::reloaded(s);
    CHECK(test::deepest_overlap(loaded) < 1e-9);
    // the tower's volume less each hole's width × thickness × height
    const double brick = 0.24 * 0.12 * 0.07, w = 0.12, hc = 0.07;
    const double holes = 0.72 * w * 14 * hc + 3 * 0.48 * w * 7 * hc;
    const auto m = test::free_mass(loaded);
    CHECK(m.mass == Approx(2000.0 * (20 * (2 * 10 + 2 * 8 - 2) * brick - holes)).epsilon(1e-9));
    // a lintel spans the door and one brick thickness on each side
    bool lintel = false;
    for (const BlockDef& b : s.blocks)
        lintel = lintel || (b.name.rfind("c014_w0_", 0) == 0 && std::abs(b.size.x() - (0.72 + 2 * w)) < 1e-9);
    CHECK(lintel);
}

TEST_CASE("an opening too close to a corner is refused", "[scene][builders]") {
    TowerSpec t{5, 5, 6, 0.24, 0.07, {{0, 0.12, 0.6, 0, 3}}};
    Scene s = test::builder_scene();
    CHECK_THROWS_WITH(add_tower(s, t), Catch::Contains("opening 0: from 0.12") && Catch::Contains("one brick length"));
}

TEST_CASE("a house keeps the caller's openings beside its door and windows, holes that meet are refused", "[scene][builders]") {
    HouseSpec h = small_house();
    // wall 1 (1.92 m): the window over [0.72, 1.2]; a second hole [0.24, 0.48] × courses 0-10
    h.walls.openings = {{1, 0.24, 0.48, 0, 10}};
    Scene s = test::builder_scene();
    add_house(s, h);
    const Scene loaded = test::reloaded(s);
    CHECK(test::deepest_overlap(loaded) < 1e-9);
    const double brick = 0.24 * 0.12 * 0.07, w = 0.12, hc = 0.07;
    const double holes = 0.72 * w * 14 * hc + 3 * 0.48 * w * 7 * hc + 0.24 * w * 10 * hc;
    const auto m = test::free_mass(loaded);
    CHECK(m.mass == Approx(2000.0 * (20 * (2 * 10 + 2 * 8 - 2) * brick - holes)).epsilon(1e-9));
    // moved 0.12 m right, its lintel's bearing meets the window's
    h.walls.openings = {{1, 0.36, 0.6, 0, 10}};
    Scene again = test::builder_scene();
    CHECK_THROWS_WITH(add_house(again, h), Catch::Contains("opening 4 meets opening 1 or its lintel in wall 1"));
}

TEST_CASE("a house whose door or windows do not fit its courses is refused, naming their options", "[scene][builders]") {
    // 14 courses of 0.07 m (0.98 m): the default windows (sill 0.9 m, 1 m high: courses 13 to 27)
    // were refused as "opening 1 ... the tower's 14 courses"
    HouseSpec h = small_house();
    h.walls.courses = 14;
    h.door_height = 0.6;
    h.window_sill = 0.9, h.window_height = 1.0;   // the generator's defaults
    Scene s = test::builder_scene();
    CHECK_THROWS_WITH(add_house(s, h), Catch::Contains("the windows (--window-sill 0.9 m, --window-height 1 m: courses "
                                                       "13 to 27) do not fit the house's 14 courses"));
    h.window_sill = 0.3, h.window_height = 0.4;
    h.door_height = 2.0;
    CHECK_THROWS_WITH(add_house(s, h), Catch::Contains("the door (--door-height 2 m, 29 courses) does not fit"));
    h.door_height = 0.6;
    CHECK_NOTHROW(add_house(s, h));
}
