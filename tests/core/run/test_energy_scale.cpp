// EnergyScale: the drift flag's scale is the energy of the motion, not gravity's reach
#include <catch2/catch.hpp>

#include "geometry/hexahedron.hpp"
#include "run/energy_scale.hpp"
#include "scene/scene_builder.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

Energies energies(double kinetic, double potential, double contact = 0.0, double external = 0.0) {
    Energies e;
    e.kinetic = kinetic;
    e.potential = potential;
    e.contact = contact;
    e.external = external;
    return e;
}

// one free 1 m cube of 2600 kg/m³ under g = 9.81 m/s²: gravity's reach m·g·√3 = 44178 J
Scene cube_scene() {
    Scene s;
    s.materials.push_back(test::stone());
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);   // fixed: no reach
    return s;
}

}  // namespace

TEST_CASE("the motion scale holds the kinetic energy and the potential actually exchanged", "[runner][energy]") {
    EnergyScale scale(cube_scene());
    const double reach = 2600.0 * 9.81 * std::sqrt(3.0);
    // a block released at rest rocks: potential 1000 J → 700 J while kinetic 0 → 300 J
    auto b0 = scale.add(energies(0.0, 1000.0));
    CHECK(b0.motion == 1.0);                          // nothing moved yet: the 1 J floor
    CHECK(b0.growth == Approx(1.0 + reach));
    auto b1 = scale.add(energies(150.0, 850.0));
    CHECK(b1.motion == Approx(150.0));                // earlier kinetic 0, potential exchanged 150 J
    auto b2 = scale.add(energies(300.0, 700.0, 5.0));
    CHECK(b2.motion == Approx(150.0 + 300.0));        // kinetic of b1, 300 J exchanged so far
    auto b3 = scale.add(energies(0.0, 1000.0));
    CHECK(b3.motion == Approx(305.0 + 300.0));        // largest kinetic + contact so far (b2)
    CHECK(b3.growth == Approx(300.0 + reach));   // gravity released 300 J; nothing moved at first
    // |work of the loads| counts now, whatever its sign
    CHECK(scale.add(energies(0.0, 1000.0, 0.0, -40.0)).motion == Approx(645.0));
}

TEST_CASE("energy appearing at a sample does not raise that sample's own scale", "[runner][energy]") {
    EnergyScale scale(cube_scene());
    scale.add(energies(10.0, 0.0));
    CHECK(scale.add(energies(1e6, 0.0)).motion == Approx(10.0));
    CHECK(scale.add(energies(0.0, 0.0)).motion == Approx(1e6));
}

TEST_CASE("the growth bar counts the run's sources, not the motion energy created on the way", "[runner][energy]") {
    EnergyScale scale(cube_scene());
    const double reach = 2600.0 * 9.81 * std::sqrt(3.0);
    scale.add(energies(80.0, 12000.0, 20.0));          // first sample: 100 J of motion
    scale.add(energies(0.0, 11000.0));                  // gravity released 1000 J
    // an unstable step launched the block: 2e5 J of kinetic, then the flight turns it into potential
    scale.add(energies(2e5, 11000.0));
    const auto flying = scale.add(energies(1e5, 1.1e5, 0.0, -30.0));
    CHECK(flying.motion == Approx(2e5 + 30.0 + 99000.0));     // the drift scale sees it all
    CHECK(flying.growth == Approx(100.0 + 30.0 + 1000.0 + reach));   // the bar does not
    // the largest |work| so far stays in the bar when the work swings back
    CHECK(scale.add(energies(0.0, 11000.0, 0.0, 5.0)).growth == Approx(100.0 + 30.0 + 1000.0 + reach));
}

TEST_CASE("the bar for energy created is the motion's energy, at least the heaviest block's m·g·diameter", "[runner][energy]") {
    Scene s = cube_scene();
    add_box(s, "C", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 1.25), false);   // a lighter free block: 1/8 of the mass, half the size
    EnergyScale scale(s);
    const double heaviest = 2600.0 * 9.81 * std::sqrt(3.0);             // the 1 m cube's, not the sum with C's
    auto b0 = scale.add(energies(0.0, 1000.0));
    CHECK(b0.created == Approx(heaviest));
    // a motion holding more than that sets the bar
    scale.add(energies(60000.0, 1000.0));
    auto b2 = scale.add(energies(0.0, 1000.0));
    CHECK(b2.created == Approx(60000.0));
}
