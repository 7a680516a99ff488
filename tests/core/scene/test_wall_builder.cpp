// the running- and English-bond walls (with openings) and the drum column: counts, no overlap,
// support, mass and centre of mass in closed form, the bond (no vertical joint of a face continues
// into the course above), nothing in a hole
#include <catch2/catch.hpp>

#include <set>

#include "builder_checks.hpp"
#include "scene/column_builder.hpp"
#include "scene/wall_builder.hpp"

using namespace cairn;

namespace {

// the box of a block (axis-aligned, as the wall builder makes them): lower and upper corners
struct Box {
    Vec3 lo, hi;
};
Box box_of(const BlockDef& b) { return {b.position - 0.5 * b.size, b.position + 0.5 * b.size}; }

// the volume two boxes share, m³
double shared_volume(const Box& a, const Box& b) {
    double v = 1.0;
    for (int k = 0; k < 3; ++k) v *= std::max(0.0, std::min(a.hi[k], b.hi[k]) - std::max(a.lo[k], b.lo[k]));
    return v;
}

// the fraction of the bottom face of block b that rests on the top face of another block
double support(const Scene& s, const BlockDef& b) {
    const Box x = box_of(b);
    double area = 0.0;
    for (const BlockDef& o : s.blocks) {
        const Box y = box_of(o);
        if (std::abs(y.hi.z() - x.lo.z()) > 1e-9) continue;
        area += std::max(0.0, std::min(x.hi.x(), y.hi.x()) - std::max(x.lo.x(), y.lo.x())) *
                std::max(0.0, std::min(x.hi.y(), y.hi.y()) - std::max(x.lo.y(), y.lo.y()));
    }
    return area / (b.size.x() * b.size.y());
}

// the least support of any free block but the lintels (which bridge their holes)
double least_support(const Scene& s) {
    double least = 1.0;
    for (const BlockDef& b : s.blocks)
        if (!b.fixed && b.name.rfind("lintel", 0) != 0) least = std::min(least, support(s, b));
    return least;
}

// the x of the vertical joints met on the front face (y = −T/2) in course c, wall ends left out, µm
std::set<long> face_joints(const Scene& s, double length, double thick, double h, int c) {
    std::set<long> out;
    for (const BlockDef& b : s.blocks) {
        const Box x = box_of(b);
        if (b.fixed || std::abs(x.lo.z() - c * h) > 1e-9 || std::abs(x.lo.y() + 0.5 * thick) > 1e-9) continue;
        for (double e : {x.lo.x(), x.hi.x()})
            if (std::abs(std::abs(e) - 0.5 * length) > 1e-9) out.insert(std::lround(e * 1e6));
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
        const auto a = face_joints(s, 1.6, 0.2, 0.1, c), b = face_joints(s, 1.6, 0.2, 0.1, c + 1);
        CHECK(!a.empty());
        for (long x : a) CHECK(b.count(x) == 0);
    }
}

TEST_CASE("a wall without base has its first course fixed, shifted courses overhang", "[scene][builders]") {
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


namespace {
// an English-bond wall of bricks 0.4 × 0.2 × h m
WallSpec english(int courses, int bricks, double h) {
    WallSpec w;
    w.courses = courses;
    w.bricks = bricks;
    w.brick = Vec3(0.4, 0.2, h);
    w.bond = WallBond::english;
    return w;
}
}  // namespace

TEST_CASE("an English-bond wall: stretcher leaves, headers with queen closers, its closed-form mass", "[scene][builders]") {
    WallSpec w = english(4, 3, 0.1);
    Scene s = test::builder_scene();
    add_wall(s, w);
    // stretcher courses: 2 leaves × 3 bricks; header courses: 2 end headers, 2 closers, 2·3 − 3 headers
    CHECK(s.blocks.size() == size_t(1 + 2 * 6 + 2 * 7));
    const Scene loaded = test::reloaded(s);
    CHECK(test::deepest_overlap(loaded) < 1e-9);
    CHECK(least_support(loaded) == Approx(1.0).epsilon(1e-9));
    // a brick length thick: the wall is 1.2 × 0.4 × 0.4 m, symmetric about x = 0 and y = 0
    CHECK(wall_thickness(w) == 0.4);
    const auto m = test::free_mass(loaded);
    CHECK(m.mass == Approx(2000.0 * 1.2 * 0.4 * 0.4).epsilon(1e-9));
    CHECK(m.centre.x() == Approx(0.0).margin(1e-9));
    CHECK(m.centre.y() == Approx(0.0).margin(1e-9));
    CHECK(m.centre.z() == Approx(0.2).epsilon(1e-9));
    int closers = 0, headers = 0;
    for (const BlockDef& b : s.blocks) {
        if (b.fixed) continue;
        if (std::abs(b.size.x() - 0.1) < 1e-9 && std::abs(b.size.y() - 0.4) < 1e-9) ++closers;   // w/2 along
        if (std::abs(b.size.x() - 0.2) < 1e-9 && std::abs(b.size.y() - 0.4) < 1e-9) ++headers;
    }
    CHECK(closers == 4);   // two per header course
    CHECK(headers == 10);  // 2 end headers + 3 per header course
    // the face joints of a course never continue into the next one
    for (int c = 0; c + 1 < w.courses; ++c) {
        const auto a = face_joints(s, 1.2, 0.4, 0.1, c), b = face_joints(s, 1.2, 0.4, 0.1, c + 1);
        CHECK(!a.empty());
        for (long x : a) CHECK(b.count(x) == 0);
    }
    WallSpec bad = w;
    bad.brick = Vec3(0.4, 0.15, 0.1);
    CHECK_THROWS_WITH(add_wall(s, bad), Catch::Contains("English bond needs the brick length (0.4 m) twice its thickness (0.15 m)"));
}

TEST_CASE("a wall with an opening: bricks cut at its sides, a lintel over it, the mass of wall minus hole", "[scene][builders]") {
    WallSpec w;
    w.courses = 4;
    w.bricks = 4;
    w.brick = Vec3(0.4, 0.2, 0.2);
    // a door of 0.4 × 0.4 m from 0.2 m, typed off the quarter-brick grid: rounded to [0.2, 0.6]
    w.openings = {{0.21, 0.0, 0.38, 0.41}};
    const auto holes = wall_holes(w);
    REQUIRE(holes.size() == 1u);
    CHECK(holes[0].x0 == Approx(0.2));
    CHECK(holes[0].x1 == Approx(0.6));
    CHECK(holes[0].course_from == 0);
    CHECK(holes[0].course_to == 2);
    Scene s = test::builder_scene();
    add_wall(s, w);
    // course 0: 4 bricks, two cut at 0.2 and 0.6 → 4 pieces; course 1 (half bricks at the ends):
    // 5 → 4; course 2: the lintel over [0, 0.8] and 2 bricks; course 3: 5
    CHECK(s.blocks.size() == size_t(1 + 4 + 4 + 3 + 5));
    const Scene loaded = test::reloaded(s);
    CHECK(test::deepest_overlap(loaded) < 1e-9);
    CHECK(least_support(loaded) == Approx(1.0).epsilon(1e-9));   // nothing rests on air
    const Box hole{Vec3(-0.8 + 0.2, -1, 0), Vec3(-0.8 + 0.6, 1, 0.4)};
    for (const BlockDef& b : loaded.blocks) CHECK(shared_volume(box_of(b), hole) < 1e-12);
    const BlockDef& lintel = loaded.blocks.back();
    CHECK(lintel.name == "lintel0");
    CHECK((lintel.size - Vec3(0.8, 0.2, 0.2)).norm() < 1e-12);
    CHECK((lintel.position - Vec3(-0.4, 0.0, 0.5)).norm() < 1e-12);
    CHECK(support(loaded, lintel) == Approx(2 * 0.2 / 0.8).epsilon(1e-9));   // half a brick each side
    // mass and centre of mass: the whole wall less the hole (volumes × centres)
    const double t = 0.2, vw = 1.6 * 0.8 * t, vo = 0.4 * 0.4 * t;
    const auto m = test::free_mass(loaded);
    CHECK(m.mass == Approx(2000.0 * (vw - vo)).epsilon(1e-9));
    CHECK(m.centre.x() == Approx((vw * 0.0 - vo * -0.4) / (vw - vo)).epsilon(1e-9));
    CHECK(m.centre.z() == Approx((vw * 0.4 - vo * 0.2) / (vw - vo)).epsilon(1e-9));
}

TEST_CASE("an English-bond wall with a door and a window weighs the wall less its holes", "[scene][builders]") {
    WallSpec w = english(8, 6, 0.2);
    // door [0.8, 1.6] × [0, 1.2], window [2.0, 2.2] × [0.6, 1.2]: their lintels meet at 1.8
    w.openings = {{0.8, 0.0, 0.8, 1.2}, {2.0, 0.6, 0.2, 0.6}};
    Scene s = test::builder_scene();
    add_wall(s, w);
    const Scene loaded = test::reloaded(s);
    CHECK(test::deepest_overlap(loaded) < 1e-9);
    CHECK(least_support(loaded) == Approx(1.0).epsilon(1e-9));
    const double t = 0.4, length = 2.4, vw = length * 1.6 * t;
    const Box door{Vec3(-1.2 + 0.8, -1, 0.0), Vec3(-1.2 + 1.6, 1, 1.2)};
    const Box window{Vec3(-1.2 + 2.0, -1, 0.6), Vec3(-1.2 + 2.2, 1, 1.2)};
    for (const BlockDef& b : loaded.blocks) {
        CHECK(shared_volume(box_of(b), door) < 1e-12);
        CHECK(shared_volume(box_of(b), window) < 1e-12);
    }
    const double vd = 0.8 * 1.2 * t, vv = 0.2 * 0.6 * t;
    const auto m = test::free_mass(loaded);
    CHECK(m.mass == Approx(2000.0 * (vw - vd - vv)).epsilon(1e-9));
    CHECK(m.centre.x() == Approx((-vd * 0.0 - vv * 0.9) / (vw - vd - vv)).epsilon(1e-9));
    CHECK(m.centre.z() == Approx((vw * 0.8 - vd * 0.6 - vv * 0.9) / (vw - vd - vv)).epsilon(1e-9));
    CHECK(m.centre.y() == Approx(0.0).margin(1e-9));
}

TEST_CASE("a wall refuses openings that do not fit, naming them", "[scene][builders]") {
    WallSpec w;   // 6 courses of 6 bricks 0.4 × 0.2 × 0.2 m: 2.4 × 1.2 m
    Scene s = test::builder_scene();
    w.openings = {{0.1, 0.0, 0.8, 0.8}};
    CHECK_THROWS_WITH(add_wall(s, w), Catch::Contains("opening 0 (x0 0.1 m") && Catch::Contains("half a brick (0.2 m) inside"));
    w.openings = {{0.4, 0.8, 0.8, 0.8}};
    CHECK_THROWS_WITH(add_wall(s, w), Catch::Contains("within the wall's height of 1.2 m"));
    w.openings = {{0.4, 0.0, 0.4, 0.8}, {1.1, 0.0, 0.4, 0.8}};   // a pier of 0.3 m
    CHECK_THROWS_WITH(add_wall(s, w), Catch::Contains("opening 1") && Catch::Contains("within a brick (0.4 m) of opening 0"));
    w.openings = {{0.4, 0.0, 0.04, 0.8}};
    CHECK_THROWS_WITH(add_wall(s, w), Catch::Contains("less than a quarter brick"));
}

TEST_CASE("a generated scene keeps its contact scheme when written and read back", "[scene][builders]") {
    // the file names the scheme whichever it is: the paper's scheme was written with no key and
    // read back as the loader's default, the overlap scheme (`cairn make wall --scheme paper`)
    Scene s = test::builder_scene();
    WallSpec w;
    w.courses = 2;
    w.bricks = 2;
    add_wall(s, w);
    s.contact.scheme = ContactScheme::paper;
    s.contact.grid_spacing = 0.05;   // m
    const Scene paper = test::reloaded(s);
    CHECK(paper.contact.scheme == ContactScheme::paper);
    CHECK(paper.contact.grid_spacing == 0.05);
    s.contact.scheme = ContactScheme::overlap;
    s.contact.subdivision = 3;
    const Scene overlap = test::reloaded(s);
    CHECK(overlap.contact.scheme == ContactScheme::overlap);
    CHECK(overlap.contact.subdivision == 3);
}
