// every scene file shipped under scenarios/ loads and validates

#include <catch2/catch.hpp>

#include <filesystem>

#include "scene/scene_io.hpp"

using namespace cairn;

TEST_CASE("every shipped scene validates", "[scene][scenarios]") {
    namespace fs = std::filesystem;
    int count = 0;
    for (const auto& e : fs::recursive_directory_iterator(fs::path(CAIRN_SOURCE_DIR) / "scenarios")) {
        if (e.path().extension() != ".toml") continue;
        INFO(e.path().string());
        CHECK_NOTHROW(load_scene(e.path().string()));
        ++count;
    }
    CHECK(count >= 3);   // at least the paper's stability and friction cases
}
