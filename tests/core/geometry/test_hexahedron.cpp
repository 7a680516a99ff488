// mass properties and convexity checks of hexahedra against closed forms

#include <catch2/catch.hpp>

#include <utility>

#include "geometry/hexahedron.hpp"

using namespace cairn;

// the 3-point Gauss rule integrates x·x·det J exactly for trilinear geometry, so every closed
// form below must hold to rounding; 1e-12 relative leaves room for summation order only

TEST_CASE("a box has m = ρabc and I = m(b² + c²)/12 about its centre", "[geometry]") {
    const double a = 0.7, b = 0.2, c = 1.0, rho = 2600;
    MassProperties mp = mass_properties(box_corners(Vec3(a, b, c)), rho);
    const double m = rho * a * b * c;
    CHECK(mp.volume == Approx(a * b * c).epsilon(1e-12));
    CHECK(mp.mass == Approx(m).epsilon(1e-12));
    CHECK(mp.centre.norm() < 1e-14);
    CHECK(mp.inertia(0, 0) == Approx(m * (b * b + c * c) / 12).epsilon(1e-12));
    CHECK(mp.inertia(1, 1) == Approx(m * (a * a + c * c) / 12).epsilon(1e-12));
    CHECK(mp.inertia(2, 2) == Approx(m * (a * a + b * b) / 12).epsilon(1e-12));
    CHECK(std::abs(mp.inertia(0, 1)) + std::abs(mp.inertia(0, 2)) + std::abs(mp.inertia(1, 2)) <
          1e-12 * m);
}

TEST_CASE("a sheared hexahedron (parallelepiped) matches the affine closed form", "[geometry]") {
    // x = x0 + E·u with u ∈ [-1/2, 1/2]³: V = det E, S = ρ V E E^T / 12, I = tr(S)·1 − S
    Mat3 e;
    e << 1.0, 0.3, 0.2,
         0.0, 0.8, -0.1,
         0.1, 0.0, 0.6;
    const Vec3 x0(2.0, -1.0, 0.5);
    const double rho = 1000;
    Corners c;
    for (int i = 0; i < 8; ++i) {
        Vec3 u(0.5 * kCornerSigns[i][0], 0.5 * kCornerSigns[i][1], 0.5 * kCornerSigns[i][2]);
        c[i] = x0 + e * u;
    }
    REQUIRE(convexity_problem(c).empty());
    MassProperties mp = mass_properties(c, rho);
    const double v = e.determinant();
    Mat3 s = rho * v * e * e.transpose() / 12.0;
    Mat3 inertia = s.trace() * Mat3::Identity() - s;
    CHECK(mp.volume == Approx(v).epsilon(1e-12));
    CHECK((mp.centre - x0).norm() < 1e-12);
    CHECK((mp.inertia - inertia).norm() < 1e-12 * inertia.norm());
}

TEST_CASE("a square frustum (trilinear, not affine) has the prismatoid volume and centroid",
          "[geometry]") {
    // bottom square side p at z = 0, top square side q at z = h
    const double p = 2.0, q = 1.0, h = 1.5;
    Corners c;
    for (int i = 0; i < 8; ++i) {
        double side = kCornerSigns[i][2] < 0 ? p : q;
        c[i] = Vec3(0.5 * side * kCornerSigns[i][0], 0.5 * side * kCornerSigns[i][1],
                    kCornerSigns[i][2] < 0 ? 0.0 : h);
    }
    REQUIRE(convexity_problem(c).empty());
    MassProperties mp = mass_properties(c, 1.0);
    CHECK(mp.volume == Approx(h * (p * p + p * q + q * q) / 3).epsilon(1e-12));
    CHECK(mp.centre.z() ==
          Approx(h * (p * p + 2 * p * q + 3 * q * q) / (4 * (p * p + p * q + q * q))).epsilon(1e-12));
    CHECK(std::abs(mp.centre.x()) + std::abs(mp.centre.y()) < 1e-14);
}

TEST_CASE("convexity_problem accepts boxes and rejects bad hexahedra with a reason",
          "[geometry]") {
    const Corners box = box_corners(Vec3(1, 1, 1));
    CHECK(convexity_problem(box).empty());

    Corners swapped = box;   // corners out of hex8 order
    std::swap(swapped[0], swapped[1]);
    CHECK_THAT(convexity_problem(swapped), Catch::Matchers::Contains("non-positive volume jacobian"));

    Corners warped = box;   // one top corner lifted: the top face is no longer planar
    warped[6].z() += 0.2;
    CHECK_THAT(convexity_problem(warped), Catch::Matchers::Contains("face 1 is not planar"));

    Corners dented = box;   // a corner pushed inside: re-entrant
    dented[6] = Vec3(0.1, 0.1, 0.1);
    CHECK_FALSE(convexity_problem(dented).empty());

    Corners flat;   // everything at one point
    flat.fill(Vec3(1, 2, 3));
    CHECK(convexity_problem(flat) == "all corners coincide");
}

TEST_CASE("a box's corners follow hex8 order", "[geometry]") {
    Corners c = box_corners(Vec3(2, 4, 6));
    CHECK(c[0] == Vec3(-1, -2, -3));
    CHECK(c[6] == Vec3(1, 2, 3));
    // every face normal (c1−c0)×(c3−c0) points away from the centre
    for (const auto& f : kFaceCorners) {
        Vec3 n = (c[f[1]] - c[f[0]]).cross(c[f[3]] - c[f[0]]);
        Vec3 mid = 0.25 * (c[f[0]] + c[f[1]] + c[f[2]] + c[f[3]]);
        CHECK(n.dot(mid) > 0);
    }
}
