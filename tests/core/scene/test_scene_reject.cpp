// every rejected input: the message names the file, the line, the key and the value as written

#include <catch2/catch.hpp>

#include "scene/scene_io.hpp"
#include "scene_fixture.hpp"

using namespace cairn;
using Catch::Matchers::Contains;
using test::error_of;
using test::with_extra;
using test::with_line;

TEST_CASE("malformed TOML names file, line and column", "[scene][reject]") {
    std::string msg = error_of(with_line(12, "size = [1, 1, 1"));
    CHECK_THAT(msg, Contains("bad.toml:13:") && Contains("TOML syntax error"));
}

TEST_CASE("an unknown top-level key is rejected", "[scene][reject]") {
    std::string msg = error_of(with_line(1, "nmae = \"t\""));
    CHECK_THAT(msg, Contains("bad.toml:1: nmae = \"t\": unknown key"));
}

TEST_CASE("an unknown key in a block is rejected", "[scene][reject]") {
    std::string msg = error_of(with_line(13, "postion = [0, 0, 0.5]"));
    CHECK_THAT(msg, Contains("bad.toml:13: blocks.A.postion = [0, 0, 0.5]: unknown key"));
}

TEST_CASE("an unknown key in contact is rejected", "[scene][reject]") {
    std::string msg = error_of(with_line(10, "friction = 0.6\nfrictoin = 0.5"));
    CHECK_THAT(msg, Contains("bad.toml:11: contact.frictoin = 0.5: unknown key"));
}

TEST_CASE("an unknown key in run is rejected", "[scene][reject]") {
    std::string msg = error_of(with_line(3, "duraton = 0.5"));
    CHECK_THAT(msg, Contains("bad.toml:3: run.duraton = 0.5: unknown key"));
}

TEST_CASE("an unknown key in a sub-table of a block is rejected", "[scene][reject]") {
    std::string msg = error_of(with_extra("[blocks.A.mesh]\ndivision = [2, 2, 2]\n"));
    CHECK_THAT(msg, Contains("bad.toml:21: blocks.A.mesh.division = [2, 2, 2]: unknown key"));
}

TEST_CASE("a negative density is rejected", "[scene][reject]") {
    std::string msg = error_of(with_line(5, "density = -2600"));
    CHECK_THAT(msg, Contains("bad.toml:5: materials.stone.density = -2600: must be > 0"));
}

TEST_CASE("a zero size is rejected", "[scene][reject]") {
    std::string msg = error_of(with_line(12, "size = [1, 0, 1]"));
    CHECK_THAT(msg, Contains("bad.toml:12: blocks.A.size = [1, 0, 1]: every edge length must be > 0"));
}

TEST_CASE("NaN and infinity are rejected", "[scene][reject]") {
    CHECK_THAT(error_of(with_line(10, "friction = nan")),
               Contains("bad.toml:10: contact.friction = nan: must be a finite number"));
    CHECK_THAT(error_of(with_line(13, "position = [0, inf, 0.5]")),
               Contains("bad.toml:13: blocks.A.position = [0, inf, 0.5]: every component must be a finite number"));
}

TEST_CASE("a value of the wrong type is rejected", "[scene][reject]") {
    CHECK_THAT(error_of(with_line(10, "friction = \"high\"")),
               Contains("bad.toml:10: contact.friction = \"high\": expected a number"));
    CHECK_THAT(error_of(with_line(19, "fixed = 1")),
               Contains("bad.toml:19: blocks.B.fixed = 1: expected true or false"));
    // a float where an integer is expected
    CHECK_THAT(error_of(with_line(3, "duration = 0.5\ncontact_interval = 2.0")),
               Contains("bad.toml:4: run.contact_interval = 2.0: expected an integer, not a float"));
    CHECK_THAT(error_of(with_line(3, "duration = 0.5\nsettle = \"yes\"")),
               Contains("bad.toml:4: run.settle = \"yes\": expected true or false"));
    CHECK_THAT(error_of(with_line(12, "size = [1, 1]")),
               Contains("bad.toml:12: blocks.A.size = [1, 1]: expected an array of 3 numbers"));
}

TEST_CASE("an integer is accepted where a float is expected", "[scene]") {
    CHECK(error_of(with_line(10, "friction = 1")).empty());
}

TEST_CASE("both contact damping keys are rejected", "[scene][reject]") {
    std::string msg = error_of(with_line(10, "friction = 0.6\ndamping_ratio = 0.1\ndamping_time = 0.01"));
    CHECK_THAT(msg, Contains("bad.toml:12: contact.damping_time = 0.01: give damping_ratio or damping_time, not both"));
}

TEST_CASE("contact scheme keys are checked against the scheme they belong to", "[scene][reject]") {
    CHECK_THAT(error_of(with_line(10, "friction = 0.6\nscheme = \"grid\"")),
               Contains("bad.toml:11: contact.scheme = \"grid\": expected \"overlap\" or \"paper\""));
    CHECK_THAT(error_of(with_line(10, "friction = 0.6\nscheme = \"overlap\"\ngrid_spacing = 0.05")),
               Contains("bad.toml:12: contact.grid_spacing = 0.05: applies to contact.scheme = \"paper\" only"));
    CHECK_THAT(error_of(with_line(10, "friction = 0.6\nscheme = \"overlap\"\nsubdivision = 17")),
               Contains("bad.toml:12: contact.subdivision = 17: must be an integer in [1, 16]"));
    CHECK_THAT(error_of(with_line(10, "friction = 0.6\nscheme = \"paper\"\nsubdivision = 4")),
               Contains("bad.toml:12: contact.subdivision = 4: applies to contact.scheme = \"overlap\" only"));
    CHECK(error_of(with_line(10, "friction = 0.6\nscheme = \"overlap\"\nsubdivision = 4")).empty());
    // the default scheme is overlap: its key alone is fine, the paper's grid is refused with a hint
    CHECK(error_of(with_line(10, "friction = 0.6\nsubdivision = 4")).empty());
    CHECK_THAT(error_of(with_line(10, "friction = 0.6\ngrid_spacing = 0.05")),
               Contains("bad.toml:11: contact.grid_spacing = 0.05: applies to contact.scheme = \"paper\" only (the "
                        "default is \"overlap\""));
}

TEST_CASE("a missing required key names the table's line", "[scene][reject]") {
    CHECK_THAT(error_of(with_line(3, "")),
               Contains("bad.toml:2: run.duration: missing required key"));
    CHECK_THAT(error_of(with_line(14, "")),
               Contains("bad.toml:11: blocks.A.material: missing required key"));
}

TEST_CASE("an unknown material is rejected", "[scene][reject]") {
    std::string msg = error_of(with_line(14, "material = \"granite\""));
    CHECK_THAT(msg, Contains("bad.toml:14: blocks.A.material = \"granite\": no material of that name"));
}

TEST_CASE("a load or probe on an unknown block is rejected", "[scene][reject]") {
    CHECK_THAT(error_of(with_extra("[loads.h]\nblock = \"C\"\nforce = [1, 0, 0]\n")),
               Contains("bad.toml:21: loads.h.block = \"C\": no block of that name"));
    CHECK_THAT(error_of(with_extra("[probes.p]\nblock = \"C\"\ncorner = 6\n")),
               Contains("bad.toml:21: probes.p.block = \"C\": no block of that name"));
}

TEST_CASE("a load on a fixed block is rejected", "[scene][reject]") {
    CHECK_THAT(error_of(with_extra("[loads.h]\nblock = \"B\"\nforce = [1, 0, 0]\n")),
               Contains("bad.toml:21: loads.h.block = \"B\": a load needs a free block"));
}

TEST_CASE("a probe with both point and corner, or a bad corner, is rejected", "[scene][reject]") {
    CHECK_THAT(error_of(with_extra("[probes.p]\nblock = \"A\"\npoint = [0, 0, 0]\ncorner = 1\n")),
               Contains("bad.toml:23: probes.p.corner = 1: give point or corner, not both"));
    CHECK_THAT(error_of(with_extra("[probes.p]\nblock = \"A\"\ncorner = 8\n")),
               Contains("bad.toml:22: probes.p.corner = 8: a corner index must be 0..7"));
}

TEST_CASE("a non-convex hexahedron is rejected with the reason", "[scene][reject]") {
    // corner 6 pushed into the block: a re-entrant corner
    std::string msg = error_of(with_line(
        12, "shape = \"hexahedron\"\ncorners = [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[0.5,0.5,0.6],[0,1,1]]"));
    CHECK_THAT(msg, Contains("bad.toml:13: blocks.A.corners = [[0,0,0],") &&
                        Contains("[0.5,0.5,0.6],[0,1,1]]: not a valid convex hexahedron: corner 6"));
    // corner 6 lifted: the top face is warped
    msg = error_of(with_line(
        12, "shape = \"hexahedron\"\ncorners = [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1.2],[0,1,1]]"));
    CHECK_THAT(msg, Contains("bad.toml:13: blocks.A.corners =") &&
                        Contains("not a valid convex hexahedron: face 1 is not planar"));
}

TEST_CASE("size with a hexahedron, or corners with a box, is rejected", "[scene][reject]") {
    CHECK_THAT(error_of(with_line(12, "size = [1, 1, 1]\ncorners = []")),
               Contains("bad.toml:13: blocks.A.corners = []: a box is given by size"));
}

TEST_CASE("a block without a free block is rejected", "[scene][reject]") {
    CHECK_THAT(error_of(with_line(14, "material = \"stone\"\nfixed = true")),
               Contains("bad.toml:") && Contains("blocks = (table): at least one block must be free"));
}

TEST_CASE("a bad orientation is rejected", "[scene][reject]") {
    CHECK_THAT(error_of(with_line(13, "orientation = {axis = [0, 0, 0], angle = 1}")),
               Contains("bad.toml:13: blocks.A.orientation.axis = [0, 0, 0]: the rotation axis must not be zero"));
    CHECK_THAT(error_of(with_line(13, "orientation = {quaternion = [1, 0, 0, 0.1]}")),
               Contains("bad.toml:13: blocks.A.orientation.quaternion = [1, 0, 0, 0.1]: a rotation quaternion must have norm 1"));
}

TEST_CASE("a missing file is rejected", "[scene][reject]") {
    try {
        load_scene("/nonexistent/dir/none.toml");
        FAIL("accepted a missing file");
    } catch (const Error& e) {
        CHECK(std::string(e.what()) == "/nonexistent/dir/none.toml: cannot open scene file");
    }
}

TEST_CASE("a backend table of any name is read, its settings are checked", "[scene][reject]") {
    // which backends exist is the registry's to say (tests/backends/engines/test_registry.cpp)
    const Scene s = parse_scene(with_extra("[backends.physx]\niterations = 10\n"), "bad.toml");
    CHECK(std::get<long long>(s.backend_settings.at("physx").at("iterations").value) == 10);
    CHECK_THAT(error_of(with_extra("[backends.dem]\nlist = [1, 2]\n")),
               Contains("bad.toml:21: backends.dem.list = [1, 2]: a backend setting must be"));
}

TEST_CASE("an unknown reference kind or parameter is rejected", "[scene][reject]") {
    CHECK_THAT(error_of(with_extra("[reference]\nkind = \"wobble\"\nblock = \"A\"\n")),
               Contains("bad.toml:21: reference.kind = \"wobble\": unknown reference kind"));
    CHECK_THAT(error_of(with_extra("[reference]\nkind = \"impact\"\nblock = \"A\"\nforce = 1\n")),
               Contains("bad.toml:23: reference.force = 1: unknown key (allowed: kind, block, gap)"));
    // the reference describes a block that moves: B is the fixed base
    CHECK_THAT(error_of(with_extra("[reference]\nkind = \"rest\"\nblock = \"B\"\n")),
               Contains("bad.toml:22: reference.block = \"B\": the reference describes a moving block; this one is fixed"));
}

TEST_CASE("a fixed node outside the mesh is rejected", "[scene][reject]") {
    CHECK_THAT(error_of(with_extra("[blocks.A.mesh]\ndivisions = [1, 1, 1]\nfixed_nodes = [0, 8]\n")),
               Contains("bad.toml:22: blocks.A.mesh.fixed_nodes = [0, 8]: node 8 is outside 0..7"));
}
