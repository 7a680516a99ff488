// `cairn run` outputs: an output directory that cannot be written is refused before the run, and a
// scene path that is not UTF-8 still gives a complete, readable result
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "cairn_process.hpp"
#include "cairn_spawn.hpp"

namespace fs = std::filesystem;
using namespace cairn::test;
using Catch::Matchers::Contains;

TEST_CASE("cairn run refuses an --out it cannot write before the run", "[app]") {
    const fs::path dir = fresh_dir("out_unwritable");
    { std::ofstream(dir / "file") << "x"; }
    // a run of hours if it started: the refusal must come first
    const pid_t pid = spawn_cairn({"run", "paper/stability", "--backend", "dem", "-q", "--set", "run.duration=1e5",
                                   "--out", (dir / "file" / "run").string()},
                                  dir);
    const Ended e = wait_for(pid);
    CHECK(e.exit_code == 2);
    CHECK_THAT(read_file(dir / "stderr.txt"), Contains("error: output directory") && Contains("file/run"));
    const auto d = wait_for(spawn_cairn({"run", "paper/stability", "--backend", "dem", "-q", "--out",
                                         (dir / "file").string(), "--force"},
                                        dir));
    CHECK(d.exit_code == 2);
    CHECK_THAT(read_file(dir / "stderr.txt"), Contains("exists and is not a directory"));
}

TEST_CASE("cairn run from a scene path that is not UTF-8 writes a complete run.json", "[app]") {
    const fs::path dir = fresh_dir("out_latin1");
    const fs::path scene = dir / "sc\xe8ne.toml";   // Latin-1 è: not UTF-8
    fs::copy_file(fs::path(CAIRN_SOURCE_DIR) / "scenarios" / "paper" / "stability.toml", scene);
    const fs::path out = dir / "run";
    const auto e = wait_for(spawn_cairn({"run", scene.string(), "--backend", "dem", "-q", "--set", "run.duration=0.05",
                                         "--out", out.string()},
                                        dir));
    CHECK(e.exit_code == 0);
    REQUIRE(fs::exists(out / "trajectory.csv"));
    const auto record = nlohmann::json::parse(read_file(out / "run.json"));
    CHECK(record["status"] == "completed");
    // the bad byte is replaced by U+FFFD, the rest of the path kept
    CHECK_THAT(record["scene"]["path"].get<std::string>(), Contains("sc\xef\xbf\xbdne.toml"));
}

TEST_CASE("cairn run --force replaces a run's files and keeps the others in the directory", "[app]") {
    const fs::path dir = fresh_dir("out_force_keeps");
    const fs::path out = dir / "run";
    const std::vector<std::string> run{"run", "paper/stability", "--backend", "dem", "-q", "--out", out.string()};
    auto with = [&](std::vector<std::string> a, const std::vector<std::string>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    REQUIRE(wait_for(spawn_cairn(with(run, {"--set", "run.duration=0.05"}), dir)).exit_code == 0);
    const std::string first = read_file(out / "trajectory.csv");
    { std::ofstream(out / "notes.txt") << "my notes\n"; }
    const auto e = wait_for(spawn_cairn(with(run, {"--force", "--set", "run.duration=0.02"}), dir));
    CHECK(e.exit_code == 0);
    CHECK(read_file(out / "notes.txt") == "my notes\n");
    CHECK(read_file(out / "trajectory.csv") != first);
}

TEST_CASE("cairn run streams its trajectory: peak memory does not grow with the run's length", "[app]") {
    const fs::path dir = fresh_dir("out_memory");
    // a row every step (dt = output interval = 1 ms): 10^4 and 10^5 rows of 22 numbers; held in
    // memory, the longer run's samples alone took 29 MB more (38 MB against 9 MB before streaming)
    auto peak = [&](const std::string& duration) {
        const Ended e = wait_for(spawn_cairn({"run", "paper/stability", "--backend", "dem", "-q", "--set",
                                              "run.dt=1e-3", "--set", "run.output_interval=1e-3", "--set",
                                              "run.duration=" + duration, "--out", (dir / duration).string()},
                                             dir));
        REQUIRE(e.exit_code == 0);
        return e.max_rss_kb;
    };
    const long short_run = peak("10");
    const long long_run = peak("100");
    CHECK(fs::file_size(dir / "100" / "trajectory.csv") > 25'000'000u);
    INFO("peak RSS " << short_run << " KiB for 10^4 steps, " << long_run << " KiB for 10^5");
    // 4 MiB: room for allocator noise, a seventh of what holding the rows cost
    CHECK(long_run - short_run < 4096);
}
