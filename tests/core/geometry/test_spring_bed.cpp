// the stiffest vibration of a rigid body on a bed of springs against closed forms

#include <catch2/catch.hpp>

#include <vector>

#include "geometry/spring_bed.hpp"

using namespace cairn;

TEST_CASE("a slab on springs at its bottom corners rocks at 3·kn·A·b²/(m(b² + c²)), faster than it bounces", "[geometry]") {
    // a 1 × 1 × 0.2 m slab of 520 kg on kn·A/4 at each bottom corner, no shear springs: it bounces
    // at kn·A/m and rocks about a bottom axis through its centre at kn·(A/4)·4·(b/2)² over
    // m(b² + c²)/12, i.e. 3·kn·A·b²/(m(b² + c²)) = 2.885·kn·A/m. An eigenvalue of a 6 × 6
    // symmetric matrix: rounding only, 1e-12
    const double a = 1.0, b = 1.0, c = 0.2, m = 520.0, kn = 1e9, area = a * b;
    std::vector<BedSpring> springs;
    for (double x : {-0.5 * a, 0.5 * a})
        for (double y : {-0.5 * b, 0.5 * b}) springs.push_back({Vec3(x, y, -0.5 * c), 0.25 * area});
    Mat3 inertia = Mat3::Zero();
    inertia.diagonal() << m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12;
    const double w2 = spring_bed_omega2(springs, Vec3::UnitZ(), kn, 0.0, Vec3::Zero(), m, inertia);
    CHECK(w2 == Approx(3.0 * kn * area * b * b / (m * (b * b + c * c))).epsilon(1e-12));
    // a tall block (c = 2 m) rocks slower than it bounces: the largest is kn·A/m
    inertia.diagonal() << m * (b * b + 4.0) / 12, m * (a * a + 4.0) / 12, m * (a * a + b * b) / 12;
    for (auto& s : springs) s.first.z() = -1.0;
    CHECK(spring_bed_omega2(springs, Vec3::UnitZ(), kn, 0.0, Vec3::Zero(), m, inertia) ==
          Approx(kn * area / m).epsilon(1e-12));
}
