// the size of a run is checked before any step: absurd step or row counts and a given dt above the
// critical step are refused naming the keys and values; nothing overflows
#include <catch2/catch.hpp>

#include "error.hpp"
#include "fake_backend.hpp"
#include "run/run_limits.hpp"
#include "run/runner.hpp"

using namespace cairn;
using namespace cairn::testing;
using Catch::Matchers::Contains;

namespace {
std::string error_of(const Scene& s, double dt, double critical, const RunLimits& limits = {}) {
    try {
        check_run_size(s, "fake", dt, critical, limits);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST_CASE("dt = 1e-30 is refused, not run as 0 steps", "[runner][limits]") {
    Scene s = ballistic_scene();
    s.source = "t.toml";
    s.run.dt = 1e-30;
    CHECK_THAT(error_of(s, 1e-30, 2e-3), Contains("t.toml: run.duration = 0.1 s with run.dt = 1e-30 is 1e+29 steps, "
                                                  "beyond the limit of 1e+09 steps (and too many to count"));
    // the runner refuses it before the first step
    FakeBackend backend;
    CHECK_THROWS_WITH(run_scene(backend, s, {}), Contains("1e+29 steps"));
}

TEST_CASE("2e9 steps are refused unless allow_large, and then counted exactly", "[runner][limits]") {
    Scene s = ballistic_scene();
    s.run.duration = 2.0;
    s.run.dt = 1e-9;
    CHECK_THAT(error_of(s, 1e-9, 0.0), Contains("run.dt = 1e-09 is 2e+09 steps, beyond the limit of 1e+09 steps "
                                                "(--allow-large lifts it"));
    RunLimits large;
    large.allow_large = true;
    s.run.output_interval = 1.0;
    const RunSize size = check_run_size(s, "fake", 1e-9, 0.0, large);
    CHECK(size.steps == 2000000000LL);   // beyond int: counted in long long
    CHECK(size.output_every == 1000000000LL);
    CHECK(size.rows == 3);
}

TEST_CASE("an auto dt that comes out at zero or tiny names contact.kn", "[runner][limits]") {
    Scene s = ballistic_scene();
    s.run.dt.reset();
    s.contact.kn = 1e300;
    CHECK_THAT(error_of(s, 0.0, 0.0), Contains("run.dt = auto gave 0 s (contact.kn = 1e+300)") &&
                                          Contains("cannot step with dt = 0 s"));
    CHECK_THAT(error_of(s, 1e-149, 1e-148),
               Contains("run.dt = auto gave 1e-149 s from the critical step 1e-148 s (contact.kn = 1e+300) is 1e+148 steps"));
}

TEST_CASE("a huge output interval samples t = 0 and the last step, never every step", "[runner][limits]") {
    Scene s = ballistic_scene();
    s.run.output_interval = 1e300;   // 1e303 steps per row: would overflow an int
    const RunSize size = check_run_size(s, "fake", 1e-3, 2e-3, {});
    CHECK(size.steps == 100);
    CHECK(size.output_every == 100);
    CHECK(size.rows == 2);
    FakeBackend backend;
    const RunResult r = run_scene(backend, s, {});
    CHECK(r.samples.size() == 2);
    CHECK(r.output_every == 100);
}

TEST_CASE("more than 1e8 rows are refused unless allow_large", "[runner][limits]") {
    Scene s = ballistic_scene();
    s.run.duration = 2.0;
    s.run.dt = 1e-8;
    s.run.output_interval = 1e-8;
    CHECK_THAT(error_of(s, 1e-8, 0.0), Contains("run.output_interval = 1e-08 s over run.duration = 2 s at dt = 1e-08 s "
                                                "is 2e+08 trajectory rows, beyond the limit of 1e+08"));
    RunLimits large;
    large.allow_large = true;
    CHECK(check_run_size(s, "fake", 1e-8, 0.0, large).rows == 200000001LL);
}

TEST_CASE("a given dt above the critical step is refused unless allow_unstable_dt", "[runner][limits]") {
    Scene s = ballistic_scene();
    s.source = "t.toml";
    s.run.dt = 3e-3;
    CHECK_THAT(error_of(s, 3e-3, 2e-3), Contains("t.toml: run.dt = 0.003: above the critical step 0.002 s of backend "
                                                 "fake (1.5 times)") && Contains("--allow-unstable-dt"));
    RunLimits allow;
    allow.allow_unstable_dt = true;
    CHECK(error_of(s, 3e-3, 2e-3, allow).empty());
    CHECK(error_of(s, 2e-3, 2e-3).empty());   // at the critical step: allowed
    CHECK(error_of(s, 3e-3, 0.0).empty());    // critical step unknown (reference engines)
    s.run.dt.reset();                          // auto: the backend chose it
    CHECK(error_of(s, 3e-3, 2e-3).empty());
    // through the runner, with the options' limits
    FakeBackend backend;
    s.run.dt = 3e-3;
    CHECK_THROWS_WITH(run_scene(backend, s, {}), Contains("above the critical step"));
    RunOptions options;
    options.limits.allow_unstable_dt = true;
    CHECK(run_scene(backend, s, options).steps == 34);
}

TEST_CASE("the memory budget defaults to half of the machine's memory", "[runner][limits]") {
    const double ram = machine_memory();
    REQUIRE(ram > 0.0);
    CHECK(memory_budget({}) == 0.5 * ram);
    RunLimits l;
    l.memory_budget = 1e9;
    CHECK(memory_budget(l) == 1e9);
    CHECK(bytes_text(1.5 * 1024 * 1024 * 1024) == "1.5 GiB");
    CHECK(bytes_text(100) == "100 B");
}
