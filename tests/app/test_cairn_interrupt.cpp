// Ctrl-C (SIGINT) on the commands that run many scenes: run-all keeps the runs it finished, each a
// complete set, and exits 130; study and bench keep their previous results whole.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "cairn_process.hpp"
#include "cairn_spawn.hpp"

namespace fs = std::filesystem;
using namespace cairn::test;
using Catch::Matchers::Contains;

namespace {

/// the directories under `root` that hold a run.json
std::vector<fs::path> run_dirs(const fs::path& root) {
    std::vector<fs::path> v;
    if (!fs::exists(root)) return v;
    for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.path().filename() == "run.json") v.push_back(e.path().parent_path());
    return v;
}

/// staging leftovers anywhere under `root`
std::vector<std::string> leftovers_under(const fs::path& root) {
    std::vector<std::string> v;
    for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.is_directory())
            for (const auto& name : leftovers(e.path())) v.push_back((e.path() / name).string());
    return v;
}

}  // namespace

TEST_CASE("SIGINT stops cairn run-all after complete runs, exit 130", "[app][kill]") {
    const fs::path dir = fresh_dir("interrupt_run_all");
    const fs::path out = dir / "out";
    const pid_t pid = spawn_cairn({"run-all", "--backends", "dem", "-q", "--out", out.string()}, dir);
    bool one_done = false;
    for (int i = 0; i < 6000 && !one_done; ++i) {
        one_done = !run_dirs(out).empty();
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ::kill(pid, SIGINT);
    const Ended e = wait_for(pid);
    REQUIRE(one_done);
    CHECK(e.exit_code == 130);
    CHECK_THAT(read_file(dir / "stderr.txt"), Contains("interrupted"));
    CHECK_THAT(read_file(dir / "stdout.txt"), Contains("scene") && Contains("final balance J"));
    size_t scenes = 0;
    for (const auto& f : fs::recursive_directory_iterator(fs::path(CAIRN_SOURCE_DIR) / "scenarios"))
        scenes += f.path().extension() == ".toml";
    const auto runs = run_dirs(out);
    CHECK(runs.size() < scenes);   // stopped before the end
    for (const auto& r : runs) {
        INFO(r.string());
        const auto record = nlohmann::json::parse(read_file(r / "run.json"));
        const std::string status = record["status"];
        CHECK(fs::exists(r / (status == "completed" ? "trajectory.csv" : "trajectory.partial.csv")));
    }
    CHECK(leftovers_under(out).empty());
}

TEST_CASE("SIGINT stops cairn study inertia and cairn bench, keeping their previous results", "[app][kill]") {
    // a study of two meshes; the bench's long resting run of 10^8 steps: minutes if left alone
    const auto [name, args] = GENERATE(table<std::string, Strings>(
        {{"study", {"study", "inertia", "--n", "1,2", "--repeats", "1", "--jobs", "1", "-q"}},
         {"bench", {"bench", "stability", "--backends", "dem", "--long-steps", "100000000", "--jobs", "1", "-q"}}}));
    const fs::path dir = fresh_dir("interrupt_" + name);
    const fs::path out = dir / name;
    fs::create_directories(out);
    { std::ofstream(out / "notes.txt") << "beside the previous results\n"; }
    const auto before = tree(out);
    const Signalled s = signal_when_staged(args + Strings{"--out", out.string()}, name, "notes.txt", SIGINT, dir);
    REQUIRE(s.staged);
    CHECK(s.ended.exit_code == 130);
    CHECK_THAT(read_file(dir / "stderr.txt"), Contains("keeps the previous"));
    CHECK(tree(out) == before);
    CHECK(leftovers(dir).empty());
}
