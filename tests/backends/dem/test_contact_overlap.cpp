// The overlap scheme's geometry: clipping and the closed-form integrals of the penetration.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "dem/contact_overlap.hpp"

using namespace cairn;
using namespace cairn::dem;

namespace {

// the target face: a square of half-side 0.5 in the plane z = 0 turned by `turn` about z,
// outward normal +z; as affine constraints "inside each edge"
std::array<Affine, 4> square_edges(double turn) {
    std::array<Affine, 4> e;
    for (int i = 0; i < 4; ++i) {
        const double a = turn + 0.5 * M_PI * i;
        const Vec3 inward(-std::cos(a), -std::sin(a), 0.0);   // from edge i back to the centre
        e[i] = Affine{inward, 0.5};                             // 0.5 − (x·outward) ≥ 0
    }
    return e;
}

bool inside_square(double x, double y, double turn) {
    const double u = std::cos(turn) * x + std::sin(turn) * y, v = -std::sin(turn) * x + std::cos(turn) * y;
    return std::abs(u) <= 0.5 && std::abs(v) <= 0.5;
}

}  // namespace

TEST_CASE("overlap clipping and its depth integrals match a fine midpoint quadrature", "[dem][contact]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    for (int trial = 0; trial < 6; ++trial) {
        // a tilted planar hitting cell z = z0 + gx·x + gy·y over a parallelogram around the origin
        const double z0 = -0.005 - 0.01 * std::abs(uni(rng)), gx = 0.05 * uni(rng), gy = 0.05 * uni(rng), turn = 0.4 * uni(rng);
        const Vec3 o(0.3 * uni(rng), 0.3 * uni(rng), 0.0), a(0.6 + 0.2 * uni(rng), 0.1 * uni(rng), 0.0),
            b(0.1 * uni(rng), 0.5 + 0.2 * uni(rng), 0.0);
        auto lift = [&](Vec3 p) { p.z() = z0 + gx * p.x() + gy * p.y(); return p; };
        ClipPolygon poly;
        poly.n = 4;
        poly.p = {lift(o - a - b), lift(o - a + b), lift(o + a + b), lift(o + a - b)};   // clockwise seen from +z
        clip(poly, Affine{Vec3(0, 0, -1), 0.0});                          // behind the plane z = 0
        for (const auto& e : square_edges(turn)) clip(poly, e);
        const OverlapIntegrals in = integrate_depth(poly, Vec3::Zero(), Vec3::UnitZ());
        // brute force: midpoint rule on a 1000 x 1000 grid over the cell's parallelogram coordinates
        const int m = 1000;
        const double jac = 4.0 * std::abs(a.x() * b.y() - a.y() * b.x()) / (double(m) * m);
        double area = 0, d1 = 0, d2 = 0;
        Vec3 mom = Vec3::Zero();
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                const Vec3 p = o + (-1.0 + (2.0 * i + 1.0) / m) * a + (-1.0 + (2.0 * j + 1.0) / m) * b;
                const double d = -(z0 + gx * p.x() + gy * p.y());
                if (d <= 0.0 || !inside_square(p.x(), p.y(), turn)) continue;
                area += jac;
                d1 += jac * d;
                d2 += jac * d * d;
                mom += jac * d * Vec3(p.x(), p.y(), 0.0);
            }
        INFO("trial " << trial << ": area " << in.area << " vs " << area);
        REQUIRE(area > 0.01);
        // a midpoint grid of h = 1/1000 of the cell misplaces the clipped boundary by ≤ h/2:
        // relative errors of a few 1e-3 at most; the closed forms are exact, 5e-3 bounds the grid
        CHECK(in.area == Approx(area).epsilon(5e-3));
        CHECK(in.d1 == Approx(d1).epsilon(5e-3));
        CHECK(in.d2 == Approx(d2).epsilon(5e-3));
        CHECK((in.moment - mom).norm() <= 5e-3 * mom.norm() + 1e-9);
        // a planar cell: the depth's gradient is −(gx, gy) everywhere, so ∫d²∇d dA = ∫d² dA·∇d
        // (rounding of the fan's sums: 1e-12)
        const Vec3 grad(-gx, -gy, 0.0);
        CHECK((in.slope - grad).norm() < 1e-12);
        CHECK((in.tilt - in.d2 * grad).norm() < 1e-12 * in.d2);
    }
}

TEST_CASE("clipping labels each edge by the constraint that cut it", "[dem][contact]") {
    // the unit square cut by x ≤ 0.6 (label 3) then y ≤ 0.7 (label 5): the edges along those
    // lines carry the labels (stored + 1), the square's own edges 0
    ClipPolygon poly;
    poly.n = 4;
    poly.p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    clip(poly, Affine{Vec3(-1, 0, 0), 0.6}, 3);
    clip(poly, Affine{Vec3(0, -1, 0), 0.7}, 5);
    REQUIRE(poly.n == 4);
    int on_x = 0, on_y = 0, own = 0;
    for (int i = 0; i < poly.n; ++i) {
        const Vec3 a = poly.p[size_t(i)], b = poly.p[size_t((i + 1) % poly.n)];
        if (poly.by[size_t(i)] == 4) on_x += std::abs(a.x() - 0.6) < 1e-15 && std::abs(b.x() - 0.6) < 1e-15;
        else if (poly.by[size_t(i)] == 6) on_y += std::abs(a.y() - 0.7) < 1e-15 && std::abs(b.y() - 0.7) < 1e-15;
        else own += poly.by[size_t(i)] == 0;
    }
    CHECK(on_x == 1);
    CHECK(on_y == 1);
    CHECK(own == 2);
}

TEST_CASE("a plane of uniform depth over a whole face integrates to area x depth exactly", "[dem][contact]") {
    ClipPolygon poly;
    poly.n = 4;
    const double d = 1e-3;
    poly.p = {Vec3(-0.5, -0.25, -d), Vec3(-0.5, 0.25, -d), Vec3(0.5, 0.25, -d), Vec3(0.5, -0.25, -d)};
    const OverlapIntegrals in = integrate_depth(poly, Vec3::Zero(), Vec3::UnitZ());
    CHECK(in.area == Approx(0.5).epsilon(1e-14));
    CHECK(in.d1 == Approx(0.5 * d).epsilon(1e-14));
    CHECK(in.d2 == Approx(0.5 * d * d).epsilon(1e-14));
    CHECK(in.moment.norm() < 1e-18);   // centred: the pressure centre is the face centre
}

TEST_CASE("clipping by a plane that misses or holds the whole polygon leaves it empty or whole", "[dem][contact]") {
    ClipPolygon poly;
    poly.n = 3;
    poly.p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    ClipPolygon all = poly;
    clip(all, Affine{Vec3(1, 0, 0), 1.0});
    CHECK(all.n == 3);
    clip(poly, Affine{Vec3(1, 0, 0), -2.0});
    CHECK(poly.n == 0);
}

TEST_CASE("the pressure centre of a face just touching is its centroid and not a quotient of rounding", "[dem][contact]") {
    // a 0.5 × 0.25 m face off the origin, tilted so that its depth changes sign across it by
    // rounding-sized amounts: ∫d is a residue of either sign, ∫x·d/∫d could lie anywhere
    const Vec3 o(1.7, -0.3, 2.1);
    for (double tilt : {1e-17, -1e-17, 3e-16}) {
        ClipPolygon poly;
        poly.n = 4;
        poly.p = {o + Vec3(0.0, 0.0, -tilt), o + Vec3(0.5, 0.0, tilt), o + Vec3(0.5, 0.25, tilt), o + Vec3(0.0, 0.25, -tilt)};
        const OverlapIntegrals in = integrate_depth(poly, o, Vec3::UnitZ());
        INFO("tilt " << tilt << ": d1 " << in.d1 << " centre " << in.pressure_centre().transpose());
        // the face's centroid (o + (0.25, 0.125, 0)), moved by at most the face's size times
        // (rounding depth / 1e-12 m): 0.5 m × 1e-15/1e-12 = 5e-4 m (at z = 2.1 a tilt of 3e-16
        // is a real one ulp, 4.4e-16 m: measured 3.7e-5 m)
        CHECK((in.pressure_centre() - (o + Vec3(0.25, 0.125, 0.0))).norm() < 5e-4);
    }
    // depth crossing zero at rounding size: d from −1e-17 m to +1.01e-17 m across x. ∫x·d/∫d
    // lies metres outside the face; the blend stays at the centroid
    {
        const Vec3 c(1.7, -0.3, 0.0);
        ClipPolygon poly;
        poly.n = 4;
        poly.p = {c + Vec3(0.0, 0.0, 1e-17), c + Vec3(0.5, 0.0, -1.01e-17), c + Vec3(0.5, 0.25, -1.01e-17), c + Vec3(0.0, 0.25, 1e-17)};
        const OverlapIntegrals in = integrate_depth(poly, c, Vec3::UnitZ());
        REQUIRE(in.d1 > 0.0);
        CHECK((in.moment / in.d1 - (c + Vec3(0.25, 0.125, 0.0))).norm() > 1.0);
        CHECK((in.pressure_centre() - (c + Vec3(0.25, 0.125, 0.0))).norm() < 1e-5);
    }
    // a real depth (1 µm to 2 µm across x): the exact ∫x·d/∫d, the 1e-12 m blend moving it by
    // less than 1e-6 of the face
    ClipPolygon poly;
    poly.n = 4;
    poly.p = {o + Vec3(0.0, 0.0, -1e-6), o + Vec3(0.5, 0.0, -2e-6), o + Vec3(0.5, 0.25, -2e-6), o + Vec3(0.0, 0.25, -1e-6)};
    const OverlapIntegrals in = integrate_depth(poly, o, Vec3::UnitZ());
    const Vec3 exact = in.moment / in.d1;
    // d = (1 + 2x) µm over x ∈ [0, 0.5] m: ∫x·d / ∫d = (5/24)/(3/4) = 5/18 m
    CHECK(exact.x() - o.x() == Approx(5.0 / 18.0).epsilon(1e-9));   // µm depths at z = 2.1: 1e-10 rounding
    CHECK((in.pressure_centre() - exact).norm() < 1e-6 * 0.5);
}
