// contacts.csv: the header names every column with its unit, a row holds the point, the normal,
// the signed normal force along it and the shear vector, numbers with 17 significant digits
#include <catch2/catch.hpp>

#include "output/contacts_csv.hpp"
#include "scene/scene_builder.hpp"

using namespace cairn;

TEST_CASE("contact rows: names, point, normal, normal force along the normal, shear", "[output]") {
    Scene s;
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);
    CHECK(contact_columns().front() == "t [s]");
    CHECK(contact_columns().size() == 13u);
    ContactPoint p;
    p.position = Vec3(0.5, -0.5, 0.0);
    p.normal = Vec3::UnitZ();
    p.normal_force = Vec3(0, 0, 6376.5);   // a quarter of 2600 kg × 9.81 m/s², pressing A up
    p.shear_force = Vec3(-12.5, 0, 0);
    p.block_a = 0;
    p.block_b = 1;
    ContactPoint unknown;
    unknown.block_a = 0;
    CHECK(contact_rows(s, 0.25, {p, unknown}) ==
          "0.25,A,B,0.5,-0.5,0,0,0,1,6376.5,-12.5,0,0\n"
          "0.25,A,?,0,0,0,0,0,1,0,0,0,0\n");
}
