// semicircular and segmental arches: voussoir volume in closed form, springers whose top is the
// springing joint, no overlap by the loader's check and by brute force
#include <catch2/catch.hpp>

#include <cmath>

#include "builder_checks.hpp"
#include "scene/arch_builder.hpp"

using namespace cairn;

TEST_CASE("arches of any subtended angle load without overlap and weigh beta R t d", "[scene][builders]") {
    for (double angle : {M_PI, 2.0 * M_PI / 3.0, M_PI / 3.0}) {
        CAPTURE(angle);
        ArchSpec a{7, 2.0, 0.3, 0.5, angle};
        Scene s = test::builder_scene();
        add_arch(s, a);
        const Scene loaded = test::reloaded(s);
        REQUIRE(loaded.blocks.size() == 9u);
        CHECK(test::deepest_overlap(loaded) < 1e-8);
        // the voussoirs are chord-sided: each section a trapezoid of area ½(re² − ri²)·sin(β/N),
        // re² − ri² = 2R·2·(t/2) = 1.2 m²; exact up to rounding of the written corners
        const auto m = test::free_mass(loaded);
        CHECK(m.mass == Approx(2000.0 * 7 * 0.5 * 1.2 * std::sin(angle / 7) * 0.5).epsilon(1e-8));
        CHECK(m.centre.x() == Approx(0.0).margin(1e-9));
    }
}

TEST_CASE("pointed arches load without overlap, are symmetric and weigh their two-centred ring", "[scene][builders]") {
    for (int n : {24, 25}) {   // even: a vertical crown joint; odd: a keystone across the crown
        CAPTURE(n);
        ArchSpec a{n, 2.0, 0.3, 0.5, M_PI, 0.1};
        Scene s = test::builder_scene();
        add_arch(s, a);
        const Scene loaded = test::reloaded(s);
        REQUIRE(loaded.blocks.size() == size_t(n) + 2);
        CHECK(test::deepest_overlap(loaded) < 1e-8);
        // voussoir i is the mirror image in x of voussoir N − 1 − i
        for (int i = 0; i < n; ++i) {
            const Corners l = arch_voussoir(a, i), r = arch_voussoir(a, n - 1 - i);
            double worst = 0.0;
            for (const Vec3& p : l) {
                double nearest = 1e300;
                for (const Vec3& q : r) nearest = std::min(nearest, (p - Vec3(-q.x(), q.y(), q.z())).norm());
                worst = std::max(worst, nearest);
            }
            CHECK(worst < 1e-12);
        }
        // each half is the part of a circle of radius ρ about (±c, 0) above z = 0 beyond the axis:
        // area ½(ρ² acos(c/ρ) − c √(ρ² − c²)); the ring is two such halves at ρ = R + c ± t/2.
        // The chord-sided voussoirs lose about φ²/6 of it (φ ≈ π/N the angle of one): < 0.5 %
        const double c = 0.1 * 2.0 * 2.0;
        auto half = [&](double rho) { return 0.5 * (rho * rho * std::acos(c / rho) - c * std::sqrt(rho * rho - c * c)); };
        const double ring = 2.0 * (half(2.0 + c + 0.15) - half(2.0 + c - 0.15));
        const auto m = test::free_mass(loaded);
        CHECK(m.mass < 2000.0 * 0.5 * ring);
        CHECK(m.mass == Approx(2000.0 * 0.5 * ring).epsilon(5e-3));
        CHECK(m.centre.x() == Approx(0.0).margin(1e-9));
        // the crown rises above a round arch's: the centreline meets the axis at √((R + c)² − c²)
        const Corners top = arch_voussoir(a, n / 2);
        CHECK(std::max(top[4].z(), top[5].z()) > 2.15);
    }
}
