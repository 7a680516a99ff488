// blocks that overlap at t = 0 are refused with the pair and the depth (separating axes, exact
// for convex hexahedra); touching blocks and small settling penetrations pass
#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/overlap.hpp"
#include "scene_fixture.hpp"

using namespace cairn;
using Catch::Matchers::Contains;
using test::error_of;
using test::with_line;

namespace {
Corners cube_at(const Vec3& centre, double angle_z = 0.0) {
    return placed_corners(box_corners(Vec3(1, 1, 1)), centre, Quat(Eigen::AngleAxisd(angle_z, Vec3::UnitZ())));
}
}  // namespace

TEST_CASE("overlap_depth of unit cubes", "[geometry][overlap]") {
    // the depth is the shortest separating translation; exact in floating point up to 1e-12
    CHECK(overlap_depth(cube_at({0, 0, 0}), cube_at({0.9, 0, 0})) == Approx(0.1).margin(1e-12));
    CHECK(overlap_depth(cube_at({0, 0, 0}), cube_at({0.3, 0.2, 0.95})) == Approx(0.05).margin(1e-12));
    CHECK(overlap_depth(cube_at({0, 0, 0}), cube_at({0, 0, 0})) == Approx(1.0).margin(1e-12));
    CHECK(overlap_depth(cube_at({0, 0, 0}), cube_at({1.0, 0, 0})) == Approx(0.0).margin(1e-12));   // touching
    CHECK(overlap_depth(cube_at({0, 0, 0}), cube_at({1.25, 0, 0})) == Approx(-0.25).margin(1e-12));
    // a cube turned 45° about z with its vertical edge 0.05 into the +x face: depth 0.05 along x
    const double h = std::sqrt(0.5);
    CHECK(overlap_depth(cube_at({0, 0, 0}), cube_at({0.5 + h - 0.05, 0, 0}, M_PI / 4)) == Approx(0.05).margin(1e-12));
    // diagonal to the corner: the bounding boxes overlap, the cubes do not (gap along (1,1,0)/√2:
    // √2·1 − 0.5 − √2/2)
    CHECK(overlap_depth(cube_at({0, 0, 0}), cube_at({1, 1, 0}, M_PI / 4)) ==
          Approx(-(std::sqrt(2.0) - 0.5 - h)).margin(1e-12));
}

TEST_CASE("two free blocks at one place are refused with the pair and the depth", "[scene][overlap]") {
    // both free: the later block in name order is named
    std::string both_free = with_line(17, "position = [0, 0, 0.5]");
    both_free.replace(both_free.find("fixed = true"), 12, "fixed = false");
    CHECK_THAT(error_of(both_free),
               Contains("bad.toml:17: blocks.B.position = [0, 0, 0.5]: block B overlaps block A by 1 m at t = 0"));
    // one fixed: the free one is named
    CHECK_THAT(error_of(with_line(13, "position = [0.3, 0, 0.45]")),
               Contains("bad.toml:13: blocks.A.position = [0.3, 0, 0.45]: block A overlaps block B by 0.05 m") &&
                   Contains("more than 1 % of the smaller block's shortest edge (1 m)"));
    // no position key: the block's table is named
    CHECK_THAT(error_of(with_line(13, "")), Contains("bad.toml:11: blocks.A = (table): block A overlaps block B by 0.5 m"));
}

TEST_CASE("touching blocks and a settling penetration within 1 % of the edge load", "[scene][overlap]") {
    CHECK(error_of(with_line(13, "position = [0, 0, 0.5]")).empty());      // touching
    CHECK(error_of(with_line(13, "position = [0, 0, 0.4905]")).empty());   // 9.5 mm into a 1 m block
    CHECK_THAT(error_of(with_line(13, "position = [0, 0, 0.4895]")), Contains("overlaps block B by 0.0105 m"));
}

TEST_CASE("overlapping fixed blocks are not refused (they never interact)", "[scene][overlap]") {
    const std::string text = test::with_extra("[blocks.C]\nsize = [1, 1, 1]\nposition = [0.5, 0, -0.5]\nmaterial = \"stone\"\nfixed = true\n");
    CHECK(error_of(text).empty());
}
