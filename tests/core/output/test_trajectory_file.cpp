// the streaming trajectory file: the same bytes as the in-memory writer, written as the run goes
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "../run/fake_backend.hpp"
#include "output/trajectory_csv.hpp"
#include "output_files.hpp"
#include "run/runner.hpp"

using namespace cairn;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return testing::scratch_dir("output/" + name); }

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
    CHECK(testing::read_all(dir / "trajectory.csv") == expected.str());
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
