// every variant of every backend has its own colour, never black (the analytic curve's)
#include <catch2/catch.hpp>

#include <set>

#include "report/palette.hpp"

TEST_CASE("the variants of the four backends have distinct colours, none black", "[report]") {
    std::set<std::string> rgb, names;
    for (const char* b : {"dem", "bullet", "ode", "mujoco"})
        for (const char* m : {"-rigid", b == std::string("dem") ? "-deformable" : "-matched"}) {
            const std::string v = std::string(b) + m;
            CHECK(cairn::report::variant_colour(v) != "#000000");
            rgb.insert(cairn::report::variant_colour(v));
            names.insert(cairn::report::variant_colour_name(v));
        }
    CHECK(rgb.size() == 8);
    CHECK(names.size() == 8);
    CHECK(rgb.count("#7f7f7f") == 0);   // grey is for names the palette does not know
}
