// Face geometry against closed forms: areas and outward normals of planar quadrilaterals, the
// projection of a point, and the hitting points' tributary areas summing to the face area.
#include <catch2/catch.hpp>

#include <cmath>

#include "dem/face.hpp"

using namespace cairn;
using dem::Quad;

namespace {

// sums of a few terms of order 1: round-off of a few ulp
constexpr double kRound = 1e-13;

// a 2 m × 0.5 m rectangle in the plane z = 1, counter-clockwise seen from +z
const Quad kRect{Vec3(0, 0, 1), Vec3(2, 0, 1), Vec3(2, 0.5, 1), Vec3(0, 0.5, 1)};
// a trapezoid in the plane x = 0: parallel sides 1 m and 3 m, 2 m apart, counter-clockwise seen from +x
const Quad kTrap{Vec3(0, -1.5, 0), Vec3(0, 1.5, 0), Vec3(0, 0.5, 2), Vec3(0, -0.5, 2)};
// a parallelogram: sides a = (2, 0, 0) and b = (1, 1, 1) from the origin
const Quad kPara{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(3, 1, 1), Vec3(1, 1, 1)};

double grid_area(const Quad& q, double spacing) {
    double sum = 0.0;
    for (const auto& h : dem::hit_grid(q, spacing)) sum += h.area;
    return sum;
}

}  // namespace

TEST_CASE("dem face: areas of planar quadrilaterals", "[dem][face]") {
    CHECK(dem::quad_area(kRect) == Approx(1.0).epsilon(kRound));
    CHECK(dem::quad_area(kTrap) == Approx(0.5 * (1.0 + 3.0) * 2.0).epsilon(kRound));   // (a + b)/2·h
    CHECK(dem::quad_area(kPara) == Approx(Vec3(2, 0, 0).cross(Vec3(1, 1, 1)).norm()).epsilon(kRound));
}

TEST_CASE("dem face: the normal points out of the counter-clockwise side", "[dem][face]") {
    for (const Vec2& xi : {Vec2(0, 0), Vec2(-1, -1), Vec2(0.3, 0.9)}) {
        CHECK((dem::quad_normal(kRect, xi) - Vec3::UnitZ()).norm() < kRound);
        CHECK((dem::quad_normal(kTrap, xi) - Vec3::UnitX()).norm() < kRound);
        CHECK((dem::quad_normal(kPara, xi) - Vec3(0, -1, 1).normalized()).norm() < kRound);
    }
    const Quad flipped{kRect[0], kRect[3], kRect[2], kRect[1]};   // clockwise: the other side
    CHECK((dem::quad_normal(flipped, Vec2::Zero()) + Vec3::UnitZ()).norm() < kRound);
}

TEST_CASE("dem face: the normal at the centre by its exact sums has the general rule's bits", "[dem][face]") {
    // quad_centre_normal adds the corners with weights ±¼ as quad_normal does at ξ = η = 0:
    // warped and skewed faces at several scales give the same bits in a portable build; a native
    // build may fuse the cross product's multiply-adds (FMA) differently in the two places, which
    // moves the last bit of a unit vector: 2 ulp of 1 allowed
    for (double scale : {1e-3, 0.37, 1.0, 250.0})
        for (int k = 0; k < 50; ++k) {
            Quad q;
            for (int i = 0; i < 4; ++i) {
                const double t = 0.9 * k + 1.7 * i;
                q[size_t(i)] = scale * (kTrap[size_t(i)] + 0.3 * Vec3(std::sin(t), std::cos(1.3 * t), std::sin(2.1 * t + 0.5)));
            }
            REQUIRE((dem::quad_centre_normal(q) - dem::quad_normal(q, Vec2::Zero())).norm() <= 4.5e-16);
        }
}

TEST_CASE("dem face: a point projects to its foot on the face", "[dem][face]") {
    // above the rectangle: ξ along x over [0, 2], η along y over [0, 0.5]
    auto p = dem::project(kRect, Vec3(1.5, 0.1, 3.0));
    CHECK((p.point - Vec3(1.5, 0.1, 1.0)).norm() < kRound);
    CHECK((p.xi - Vec2(0.5, -0.6)).norm() < kRound);
    // the trapezoid is not a parallelogram (Gauss-Newton iterates): a point 0.7 m off its surface
    // point at (ξ, η) = (0.4, -0.2) comes back to it; the iteration stops at a step of 1e-13
    const Vec2 xi0(0.4, -0.2);
    const Vec3 foot = dem::quad_point(kTrap, xi0);
    auto t = dem::project(kTrap, foot + 0.7 * Vec3::UnitX());
    CHECK((t.xi - xi0).norm() < 1e-10);
    CHECK((t.point - foot).norm() < 1e-10);
    // points outside the face keep unclamped coordinates
    CHECK(dem::project(kRect, Vec3(3.0, 0.25, 1.0)).xi[0] == Approx(2.0).epsilon(kRound));
}

TEST_CASE("dem face: the parallelogram frame projects as the general rule does", "[dem][face]") {
    CHECK_FALSE(dem::ParallelogramFrame::of(kTrap).valid);
    const auto f = dem::ParallelogramFrame::of(kPara);
    REQUIRE(f.valid);
    CHECK(f.det == Approx(Vec3(1, 0, 0).cross(Vec3(0.5, 0.5, 0.5)).squaredNorm()).epsilon(kRound));   // |a×b|²
    for (const Vec3& p : {Vec3(1.5, 0.5, 0.5), Vec3(4, -2, 3), Vec3(0, 0, 0)}) {
        const auto a = f.project(p), b = dem::project(kPara, p);
        CHECK((a.xi - b.xi).norm() < 1e-12);
        CHECK((a.point - b.point).norm() < 1e-12);
        CHECK((p - a.point).cross(f.n).norm() < 1e-12);   // the offset is along the normal
    }
}

TEST_CASE("dem face: hitting points' tributary areas sum to the face area", "[dem][face]") {
    // the jacobian of a planar bilinear face is linear in each coordinate, so the trapezoid rule
    // integrates it exactly: the sum is the area to round-off, for any spacing
    for (double spacing : {5.0, 0.3, 0.07}) {
        CHECK(grid_area(kRect, spacing) == Approx(dem::quad_area(kRect)).epsilon(kRound));
        CHECK(grid_area(kTrap, spacing) == Approx(dem::quad_area(kTrap)).epsilon(kRound));
        CHECK(grid_area(kPara, spacing) == Approx(dem::quad_area(kPara)).epsilon(kRound));
    }
    // counts: ⌈longest edge / spacing⌉ + 1 per direction, at least the two corners
    CHECK(dem::hit_grid_counts(kRect, 0.3) == std::array<int, 2>{8, 3});   // ⌈2/0.3⌉ + 1, ⌈0.5/0.3⌉ + 1
    CHECK(dem::hit_grid_counts(kRect, 0.5) == std::array<int, 2>{5, 2});   // exact multiples: no extra point
    CHECK(dem::hit_grid_counts(kRect, 5.0) == std::array<int, 2>{2, 2});
    // a spacing above the face leaves the 4 corners, a quarter of the rectangle each
    const auto corners = dem::hit_grid(kRect, 5.0);
    REQUIRE(corners.size() == 4);
    for (const auto& h : corners) {
        CHECK(std::abs(h.xi[0]) == 1.0);
        CHECK(h.area == Approx(0.25).epsilon(kRound));
    }
}
