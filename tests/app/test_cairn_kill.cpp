// Results as a set: cairn killed (SIGKILL) at random moments leaves in DIR either the old complete
// result or the new complete result, never a mix or a partial file under the final names; SIGINT
// and SIGTERM stop a run cleanly (exit 130, status interrupted, partial trajectory kept) and stop
// validate keeping its previous report.
#include <catch2/catch.hpp>

#include <chrono>
#include <map>
#include <random>
#include <thread>

#include <nlohmann/json.hpp>

#include "cairn_process.hpp"
#include "cairn_spawn.hpp"

namespace fs = std::filesystem;
using namespace cairn::test;
using Catch::Matchers::Contains;

namespace {

std::vector<std::string> keys(const std::map<std::string, std::string>& t) {
    std::vector<std::string> k;
    for (const auto& [name, text] : t) k.push_back(name);
    return k;
}

/// run.json without the wall time, the one field that differs between two runs of one input
nlohmann::json record_of(const std::string& text) {
    auto j = nlohmann::json::parse(text);
    j.erase("wall_seconds");
    return j;
}

/// run cairn to its end; returns the wall time, s
double run_ok(const Strings& args, const fs::path& scratch) {
    const auto t0 = std::chrono::steady_clock::now();
    const Ended e = wait_for(spawn_cairn(args, scratch));
    REQUIRE(e.exit_code == 0);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// seeded delays: kill points spread over the whole run, the swap at its end included
std::vector<double> kill_delays(int count, double run_seconds, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.3 * run_seconds);
    std::vector<double> d;
    for (int i = 0; i < count; ++i) d.push_back(u(rng));
    return d;
}

/// put a copy of `old` at `target`, start `cairn args...`, SIGKILL it after `delay` s; returns what
/// `target` holds then
std::map<std::string, std::string> kill_during(const Strings& args, const fs::path& old, const fs::path& target,
                                               double delay, const fs::path& scratch) {
    fs::remove_all(target);
    fs::copy(old, target, fs::copy_options::recursive);
    const pid_t pid = spawn_cairn(args, scratch);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    ::kill(pid, SIGKILL);
    wait_for(pid);
    return tree(target);
}

/// the two complete results a killed command may leave: the old one, and the one it computes
struct Known {
    Strings new_args;                           ///< the command of the new result, without --out
    double seconds = 0.0;                       ///< its wall time, s
    std::map<std::string, std::string> old_tree, new_tree;
};

/// run `base` with --set `old_set` into dir/old and with --set `new_set` into dir/new
Known known_results(const Strings& base, const std::string& old_set, const std::string& new_set, const fs::path& dir) {
    Known k;
    k.new_args = base + Strings{"--set", new_set};
    run_ok(base + Strings{"--set", old_set, "--out", (dir / "old").string()}, dir);
    k.seconds = run_ok(k.new_args + Strings{"--out", (dir / "new").string()}, dir);
    k.old_tree = tree(dir / "old");
    k.new_tree = tree(dir / "new");
    return k;
}

/// one thread per child: the kill points are spread over the run's length, which two OpenMP threads
/// waiting on a core shared with other jobs can stretch tenfold (results do not depend on it)
const bool kOneThread = ::setenv("OMP_NUM_THREADS", "1", 1) == 0;

}  // namespace

TEST_CASE("cairn run killed at random moments leaves the old or the new result, never a mix", "[app][kill]") {
    const fs::path dir = fresh_dir("kill_run");
    const Known k = known_results({"run", "paper/stability", "--backend", "dem", "-q"}, "run.duration=5",
                                  "run.duration=10", dir);
    const auto& [new_args, seconds, old_tree, new_tree] = k;
    REQUIRE(keys(old_tree) == Strings{"run.json", "trajectory.csv"});
    REQUIRE(old_tree.at("trajectory.csv") != new_tree.at("trajectory.csv"));

    const fs::path target = dir / "target";
    int saw_old = 0, saw_new = 0;
    for (double delay : kill_delays(16, seconds, 20261123u)) {
        const auto t = kill_during(new_args + Strings{"--force", "--out", target.string()}, dir / "old", target,
                                   delay, dir);
        INFO("killed after " << delay << " s of a " << seconds << " s run");
        // only the two final names: no partial trajectory, no temporary file
        REQUIRE(keys(t) == Strings{"run.json", "trajectory.csv"});
        const bool is_old = t.at("trajectory.csv") == old_tree.at("trajectory.csv") &&
                            record_of(t.at("run.json")) == record_of(old_tree.at("run.json"));
        const bool is_new = t.at("trajectory.csv") == new_tree.at("trajectory.csv") &&
                            record_of(t.at("run.json")) == record_of(new_tree.at("run.json"));
        CHECK((is_old || is_new));
        saw_old += is_old;
        saw_new += is_new;
    }
    INFO("old " << saw_old << ", new " << saw_new);
    CHECK(saw_old > 0);   // kills within the first tenth of the run surely land before the swap
    // a finished run removes the staging directories the killed ones left
    run_ok(new_args + Strings{"--force", "--out", target.string()}, dir);
    CHECK(leftovers(dir).empty());
}

TEST_CASE("cairn validate killed at random moments keeps the old report or the new one whole", "[app][kill]") {
    const fs::path dir = fresh_dir("kill_validate");
    const Known k = known_results({"validate", "--cases", "stability", "--backends", "dem", "--jobs", "1", "-q"},
                                  "run.duration=0.2", "run.duration=0.3", dir);
    const auto& [new_args, seconds, old_tree, new_tree] = k;
    REQUIRE(old_tree.count("runs/stability/dem-rigid/trajectory.csv") == 1);

    const fs::path target = dir / "target";
    int saw_old = 0;
    for (double delay : kill_delays(6, seconds, 7u)) {
        const auto t = kill_during(new_args + Strings{"--out", target.string()}, dir / "old", target, delay, dir);
        INFO("killed after " << delay << " s of a " << seconds << " s validation");
        const bool is_old = t == old_tree;
        // the new report whole: every file there, the runs' trajectories and records as computed
        bool is_new = keys(t) == keys(new_tree);
        for (const auto& [name, text] : new_tree) {
            if (!is_new) break;
            if (name.size() > 4 && name.compare(name.size() - 4, 4, ".csv") == 0 && name.rfind("runs/", 0) == 0)
                is_new = t.at(name) == text;
            if (name.size() > 8 && name.compare(name.size() - 8, 8, "run.json") == 0)
                is_new = record_of(t.at(name)) == record_of(text);
        }
        CHECK((is_old || is_new));
        saw_old += is_old;
    }
    CHECK(saw_old > 0);
}

TEST_CASE("SIGINT or SIGTERM stops cairn run with status interrupted and the partial trajectory", "[app][kill]") {
    const int sig = GENERATE(SIGINT, SIGTERM);
    const fs::path dir = fresh_dir("interrupt_run_" + std::to_string(sig));
    const fs::path out = dir / "run";
    // a run of hours if left alone
    const Signalled s = signal_when_staged(
        {"run", "paper/stability", "--backend", "dem", "-q", "--set", "run.duration=1e5", "--out", out.string()}, "run",
        "trajectory.csv", sig, dir);
    REQUIRE(s.staged);
    const Ended& e = s.ended;
    CHECK(e.exit_code == 130);
    CHECK_THAT(read_file(dir / "stderr.txt"), Contains("interrupted at t = ") && Contains("trajectory.partial.csv"));
    CHECK_FALSE(fs::exists(out / "trajectory.csv"));
    const auto record = nlohmann::json::parse(read_file(out / "run.json"));
    CHECK(record["status"] == "interrupted");
    CHECK(record["partial"] == true);
    CHECK_THAT(record["message"].get<std::string>(), Contains("interrupted at t = "));
    // the partial trajectory: the header, rows up to the stop, its last row the state at the stop
    const std::string csv = read_file(out / "trajectory.partial.csv");
    REQUIRE(!csv.empty());
    CHECK(csv.back() == '\n');
    const auto last_line = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
    const double t_last = std::stod(last_line.substr(0, last_line.find(',')));
    CHECK(t_last > 0.0);
    CHECK(t_last < 1e5);
    CHECK(t_last == record["final_time"].get<double>());
    CHECK(record["samples"].get<long long>() ==
          (long long)std::count(csv.begin(), csv.end(), '\n') - 1);
    CHECK(leftovers(dir).empty());
}

TEST_CASE("SIGINT stops cairn validate and keeps the previous report", "[app][kill]") {
    const fs::path dir = fresh_dir("interrupt_validate");
    const fs::path out = dir / "validation";
    const Strings validate{"validate", "--cases", "stability", "--backends", "dem", "-q", "--out", out.string()};
    run_ok(validate + Strings{"--set", "run.duration=0.2"}, dir);
    const auto before = tree(out);
    const Signalled s = signal_when_staged(validate + Strings{"--set", "run.duration=1e5"}, "validation", "runs", SIGINT, dir);
    REQUIRE(s.staged);
    const Ended& e = s.ended;
    CHECK(e.exit_code == 130);
    CHECK_THAT(read_file(dir / "stderr.txt"), Contains("interrupted") && Contains("keeps the previous"));
    CHECK(tree(out) == before);
    CHECK(leftovers(dir).empty());
}
