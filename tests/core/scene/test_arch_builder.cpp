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
