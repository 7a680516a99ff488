// the streaming trajectory file: the same bytes as the in-memory writer, written as the run goes
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "../run/fake_backend.hpp"
#include "output/trajectory_csv.hpp"
#include "run/runner.hpp"

using namespace cairn;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

fs::path scratch(const std::string& name) {
    const auto dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "output" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

}  // namespace

TEST_CASE("a trajectory streamed to a file has the bytes of the in-memory writer", "[output]") {
    const Scene scene = testing::ballistic_scene();
    const fs::path dir = scratch("stream_same_bytes");
    testing::FakeBackend a, b;
    TrajectoryCsvFile file((dir / "trajectory.csv").string());
    const RunResult streamed = run_scene(a, scene, {}, file);
    const RunResult collected = run_scene(b, scene, {});
    std::ostringstream expected;
    write_trajectory_csv(expected, scene, collected.samples);
    REQUIRE(streamed.sample_count == 11);
    CHECK(slurp(dir / "trajectory.csv") == expected.str());
}

TEST_CASE("a trajectory file that cannot be created names it", "[output]") {
    const Scene scene = testing::ballistic_scene();
    const fs::path dir = scratch("stream_no_dir");
    testing::FakeBackend backend;
    TrajectoryCsvFile file((dir / "missing" / "trajectory.csv").string());
    CHECK_THROWS_WITH(run_scene(backend, scene, {}, file), Catch::Matchers::Contains("missing/trajectory.csv"));
}

TEST_CASE("a full disk while streaming is an error naming the file", "[output]") {
    // /dev/full accepts the open and fails every write with ENOSPC
    if (!fs::exists("/dev/full")) return;
    const Scene scene = testing::ballistic_scene();
    testing::FakeBackend backend;
    TrajectoryCsvFile file("/dev/full");
    CHECK_THROWS_WITH(run_scene(backend, scene, {}, file),
                      Catch::Matchers::Contains("/dev/full") && Catch::Matchers::Contains("disk full"));
}
