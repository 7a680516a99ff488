// --set overrides: set into the document before validation, reported as "--set key"

#include <catch2/catch.hpp>

#include "scene/scene_io.hpp"
#include "scene_fixture.hpp"

using namespace cairn;
using Catch::Matchers::Contains;

namespace {
Scene with(const std::vector<std::string>& sets) {
    std::vector<Override> o;
    for (const auto& s : sets) o.push_back(parse_override(s));
    return parse_scene(test::kBaseScene, "base.toml", o);
}
}  // namespace

TEST_CASE("parse_override splits at the first '='", "[scene][override]") {
    Override o = parse_override("a.b=c=d");
    CHECK(o.key == "a.b");
    CHECK(o.value == "c=d");
    CHECK_THROWS_AS(parse_override("novalue"), Error);
    CHECK_THROWS_AS(parse_override("=1"), Error);
}

TEST_CASE("an override replaces a value", "[scene][override]") {
    Scene s = with({"contact.friction=0.4"});
    CHECK(s.contact.friction == 0.4);
}

TEST_CASE("an override adds an array and new tables", "[scene][override]") {
    Scene s = with({"blocks.A.velocity=[1, 2, 3]", "damping.alpha=2", "backends.dem.x=3"});
    CHECK(s.blocks[0].velocity == Vec3(1, 2, 3));
    CHECK(s.damping.alpha == 2.0);
    CHECK(s.backend_settings.at("dem").at("x").origin == "--set backends.dem.x");
}

TEST_CASE("an override that is not TOML is taken as a string", "[scene][override]") {
    Scene s = with({"run.dt=1e-4", "run.dt=auto"});
    CHECK_FALSE(s.run.dt.has_value());
    Scene n = with({"name=my scene"});
    CHECK(n.name == "my scene");
}

TEST_CASE("an override typo is rejected naming --set", "[scene][override]") {
    std::string msg = test::error_of(test::kBaseScene, {parse_override("contact.fricton=0.4")});
    CHECK_THAT(msg, Contains("--set contact.fricton: contact.fricton = 0.4: unknown key"));
}

TEST_CASE("a bad overridden value is reported as --set", "[scene][override]") {
    std::string msg = test::error_of(test::kBaseScene, {parse_override("materials.stone.density=-1")});
    CHECK_THAT(msg, Contains("--set materials.stone.density: materials.stone.density = -1: must be > 0"));
}

TEST_CASE("an override through a value that is not a table is rejected", "[scene][override]") {
    std::string msg = test::error_of(test::kBaseScene, {parse_override("contact.kn.x=1")});
    CHECK_THAT(msg, Contains("--set contact.kn.x") && Contains("contact.kn is not a table"));
}

TEST_CASE("a contact.scheme override switches a scene that gives the other scheme's key", "[scene][override]") {
    auto parse = [](const std::string& contact, const std::vector<std::string>& sets) {
        std::string text = test::kBaseScene;
        const auto at = text.find("[contact]\n");
        REQUIRE(at != std::string::npos);
        text.insert(at + 10, contact);
        std::vector<Override> o;
        for (const auto& s : sets) o.push_back(parse_override(s));
        return parse_scene(text, "base.toml", o);
    };
    // a made arch states scheme = "overlap" with its subdivision: the paper scheme drops it
    const Scene paper = parse("scheme = \"overlap\"\nsubdivision = 1\n", {"contact.scheme=paper"});
    CHECK(paper.contact.scheme == ContactScheme::paper);
    const Scene overlap = parse("scheme = \"paper\"\ngrid_spacing = 0.05\n", {"contact.scheme=\"overlap\""});
    CHECK(overlap.contact.scheme == ContactScheme::overlap);
    // the other scheme's key given on the command line is still refused, in either order
    CHECK_THROWS_WITH(parse("scheme = \"overlap\"\n", {"contact.scheme=paper", "contact.subdivision=2"}),
                      Contains("--set contact.subdivision") && Contains("applies to contact.scheme = \"overlap\" only"));
    CHECK_THROWS_WITH(parse("scheme = \"overlap\"\n", {"contact.subdivision=2", "contact.scheme=paper"}),
                      Contains("applies to contact.scheme = \"overlap\" only"));
    // without the switch the file's contradiction is still an error
    CHECK_THROWS_WITH(parse("scheme = \"paper\"\nsubdivision = 4\n", {}),
                      Contains("applies to contact.scheme = \"overlap\" only"));
}
