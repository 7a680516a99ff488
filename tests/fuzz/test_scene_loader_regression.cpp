// inputs the scene-loader fuzzer once found to escape the loader: each now loads or is refused
// with a cairn::Error, and nothing else
#include <catch2/catch.hpp>

#include <sstream>

#include "error.hpp"
#include "scene_input.hpp"

namespace fs = std::filesystem;

TEST_CASE("fuzz regression inputs load or are refused with a cairn::Error", "[fuzz][scene]") {
    const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "fuzz";
    fs::create_directories(dir);
    int n = 0;
    for (const auto& e : fs::directory_iterator(fs::path(CAIRN_SOURCE_DIR) / "tests" / "fuzz" / "inputs")) {
        std::ifstream in(e.path(), std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        INFO(e.path().filename().string());
        try {
            cairn::fuzz::load_input(ss.str(), dir);
        } catch (const cairn::Error& err) {
            CHECK(std::string(err.what()).size() > 0);
        }
        ++n;   // reached only when nothing but a cairn::Error escaped
    }
    CHECK(n > 0);
}

TEST_CASE("a --set value toml++ cannot read even as a string is a cairn::Error naming the key", "[fuzz][scene]") {
    const std::string scene = "[run]\nduration = 1.0\n";
    CHECK_THROWS_AS(cairn::parse_scene(scene, "<test>", {{"run.duration", std::string("a\x01") + "b"}}), cairn::Error);
    CHECK_THROWS_WITH(cairn::parse_scene(scene, "<test>", {{"run.duration", std::string("\x10\0x", 3)}}),
                      Catch::Matchers::Contains("--set run.duration"));
}
