// The paper scheme's point-to-face rule at the edge of a target side: a hitting point that lies
// past a neighbour's edge (nearer another side plane than the one it would act on) is not pushed
// through that side (renaming and reordering: test_contact_scheme_overlap.cpp, both schemes).
#include <catch2/catch.hpp>

#include "dem_test_util.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

constexpr double kKn = 3e7;   // N/m³

}  // namespace

TEST_CASE("paper scheme: a point just past a neighbour's edge is not pushed through its side", "[dem][contact]") {
    // T, a 0.4 x 0.2 x 0.2 m brick, and H, 0.2 x 0.1 x 0.2 m (T's sides are the larger: T is the
    // target of H's bottom and of H's -x side), H overlapping T's top +x edge by ex = 1 cm along x
    // and ez = 1 mm along z, clear of T's y sides. The bottom row of H's -x side lies ex behind
    // T's +x side but only ez under T's top: it came down through the top, past the +x side's
    // edge. The old rule let it act on the +x side (any other side nearer by under a quarter of
    // T's edge, 5 cm): kn·(0.005 m²)·ex = 1500 N along +x, pushing H out sideways
    const double ex = 0.01, ez = 0.001;
    Scene s = test::stone_scene();
    s.contact.scheme = ContactScheme::paper;
    s.contact.kn = s.contact.ks = kKn;
    s.contact.grid_spacing = 0.1;
    add_box(s, "T", Vec3(0.4, 0.2, 0.2), Vec3(0, 0, 0.1), true);
    add_box(s, "H", Vec3(0.2, 0.1, 0.2), Vec3(0.3 - ex, 0, 0.3 - ez), false);
    const Vec3 f = test::contact_resultant(s, 1);
    INFO("force on H " << f.transpose() << " N");
    // what acts is the row of H's bottom over T (x = 0.19 m, tributary 0.05 x 0.1 m): kn·A·ez up;
    // exact but for round-off of positions of order 1 m (1e-9 of the force)
    const double row = 0.05 * 0.1;
    CHECK(f.z() == Approx(kKn * row * ez).epsilon(1e-9));
    CHECK(std::abs(f.x()) < 1e-9 * kKn * row * ez);
    CHECK(std::abs(f.y()) < 1e-9 * kKn * row * ez);
}

TEST_CASE("paper scheme: a point that comes in through its side acts on it", "[dem][contact]") {
    // the same blocks with H beside T, its -x side pressed ex into T's +x side, its top, bottom
    // and sides flush with T's. A point new to a side acts only if no other side plane is nearer
    // by more than the flush tolerance (1e-4 of T's shortest edge, 2e-5 m) plus its step's travel
    // (none here): the edge rows (on T's top, bottom and side planes) are, at ex = 1e-5 m
    const double ex = 1e-5, ez = 0.0;
    Scene s = test::stone_scene();
    s.contact.scheme = ContactScheme::paper;
    s.contact.kn = s.contact.ks = kKn;
    s.contact.grid_spacing = 0.1;
    add_box(s, "T", Vec3(0.4, 0.2, 0.2), Vec3(0, 0, 0.1), true);
    add_box(s, "H", Vec3(0.2, 0.2, 0.2), Vec3(0.3 - ex, 0, 0.1 + ez), false);
    const Vec3 f = test::contact_resultant(s, 1);
    INFO("force on H " << f.transpose() << " N");
    // the whole 0.2 x 0.2 m side is over T's side (its edges flush with T's): kn·A·ex along +x
    CHECK(f.x() == Approx(kKn * 0.04 * ex).epsilon(1e-9));
    CHECK(std::abs(f.z()) < 1e-9 * kKn * 0.04 * ex);
}
