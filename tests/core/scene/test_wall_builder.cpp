// the running-bond wall and the drum column: counts, no overlap, mass and centre of mass in closed
// form, the bond (no vertical joint continues into the course above)
#include <catch2/catch.hpp>

#include <set>

#include "builder_checks.hpp"
#include "scene/column_builder.hpp"
#include "scene/wall_builder.hpp"

using namespace cairn;

namespace {
// the x of the vertical joints inside course c (block ends, wall ends left out)
std::set<long> joints(const Scene& s, const WallSpec& w, int c) {
    std::set<long> out;
    const double half = 0.5 * w.brick.x() * w.bricks;
    for (const BlockDef& b : s.blocks) {
        if (b.fixed || std::stoi(b.name.substr(1, 3)) != c) continue;
        for (double x : {b.position.x() - 0.5 * b.size.x(), b.position.x() + 0.5 * b.size.x()})
            if (std::abs(std::abs(x) - half) > 1e-9) out.insert(std::lround(x * 1e6));   // µm
    }
    return out;
}
}  // namespace

TEST_CASE("a running-bond wall loads, touches without overlap, weighs its closed form", "[scene][builders]") {
    WallSpec w;
    w.courses = 5;
    w.bricks = 4;
    w.brick = Vec3(0.4, 0.2, 0.1);
    Scene s = test::builder_scene();
    add_wall(s, w);
    // odd courses: bricks − 1 whole bricks and two halves
    CHECK(s.blocks.size() == size_t(1 + 3 * 4 + 2 * 5));
    const Scene loaded = test::reloaded(s);   // the loader refuses overlaps beyond 1 % of an edge
    CHECK(loaded.blocks.size() == s.blocks.size());
    // touching faces: the exact separating-axis depth is 0 up to rounding of the written numbers
    CHECK(test::deepest_overlap(loaded) < 1e-9);
    // every course holds the volume of `bricks` bricks; the wall is symmetric about x = 0
    const auto m = test::free_mass(loaded);
    CHECK(m.mass == Approx(2000.0 * 5 * 4 * 0.4 * 0.2 * 0.1).epsilon(1e-9));
    CHECK(m.centre.x() == Approx(0.0).margin(1e-9));
    CHECK(m.centre.z() == Approx(0.25).epsilon(1e-9));   // half of 5 × 0.1 m
    // running bond: no joint of a course continues into the next
    for (int c = 0; c + 1 < w.courses; ++c) {
        const auto a = joints(s, w, c), b = joints(s, w, c + 1);
        for (long x : a) CHECK(b.count(x) == 0);
    }
}

TEST_CASE("a wall without base has its first course fixed; shifted courses overhang", "[scene][builders]") {
    WallSpec w;
    w.courses = 3;
    w.bricks = 3;
    w.base = false;
    w.half_bricks = false;
    Scene s = test::builder_scene();
    add_wall(s, w);
    REQUIRE(s.blocks.size() == 9u);
    for (int i = 0; i < 9; ++i) CHECK(s.blocks[size_t(i)].fixed == (i < 3));
    // course 1 is shifted by half a brick: its centre of mass is 0.2 m to the right
    CHECK(s.blocks[4].position.x() == Approx(0.2).margin(1e-12));
    CHECK(test::reloaded(s).blocks.size() == 9u);
}

TEST_CASE("a drum column stacks its drums on the base", "[scene][builders]") {
    Scene s = test::builder_scene();
    add_column(s, ColumnSpec{3, 0.3, 0.5, true});
    const Scene loaded = test::reloaded(s);
    REQUIRE(loaded.blocks.size() == 4u);
    CHECK(test::deepest_overlap(loaded) < 1e-9);
    const auto m = test::free_mass(loaded);
    CHECK(m.count == 3);
    CHECK(m.mass == Approx(2000.0 * 3 * 0.3 * 0.3 * 0.5).epsilon(1e-12));
    CHECK(m.centre.z() == Approx(0.75).epsilon(1e-12));
}
