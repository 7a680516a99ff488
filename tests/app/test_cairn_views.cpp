// the 3-D views of `cairn run` (--vtk, --replay) and `cairn replay`: bad input and refusals
#include <catch2/catch.hpp>

#include <algorithm>

#include "cairn_process.hpp"

namespace fs = std::filesystem;
using namespace cairn::test;
using Catch::Matchers::Contains;

TEST_CASE("cairn replay of a directory that is not a run exits 2 naming the file and writes nothing", "[app]") {
    const auto dir = fresh_dir("replay_bad");
    fs::create_directories(dir / "empty");
    const auto page = dir / "page.html";
    const auto r = run_cairn("replay '" + (dir / "empty").string() + "' -o '" + page.string() + "'", dir);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Contains((dir / "empty" / "run.json").string()));
    CHECK_FALSE(fs::exists(page));
}

TEST_CASE("cairn run --vtk that the backend refuses leaves no output directory", "[app]") {
    const auto dir = fresh_dir("vtk_refused");
    // --model deformable makes the falling cube deformable, which bullet refuses
    const auto r = run_cairn("run paper/impact -b bullet --model deformable --vtk --replay -q -o '" +
                                 (dir / "out").string() + "'", dir);
    if (r.exit_code == 2 && r.err.find("unknown backend") != std::string::npos) {
        WARN("bullet is not built: nothing to check");
        return;
    }
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Contains("cannot represent deformable block"));
    CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("cairn run --vtk --force replaces an earlier run's series", "[app]") {
    const auto dir = fresh_dir("vtk_force");
    const std::string out = (dir / "out").string();
    auto files = [&] { return size_t(std::distance(fs::directory_iterator(dir / "out" / "vtk"), fs::directory_iterator{})); };
    auto samples = [&] {
        const std::string csv = read_file(dir / "out" / "trajectory.csv");
        return size_t(std::count(csv.begin(), csv.end(), '\n')) - 1;   // minus the header
    };
    REQUIRE(run_cairn("run paper/impact -b dem -q --vtk -o '" + out + "' --set run.duration=0.02", dir).exit_code == 0);
    CHECK(files() == 2 * samples() + 2);   // blocks and contacts per sample, two .pvd
    const size_t long_run = files();
    REQUIRE(run_cairn("run paper/impact -b dem -q --vtk --force -o '" + out + "' --set run.duration=0.01", dir).exit_code == 0);
    // none of the longer run's files is left
    CHECK(files() == 2 * samples() + 2);
    CHECK(files() < long_run);
}
