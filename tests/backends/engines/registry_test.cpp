// A new backend is its folder, CMake and one registry line: a test double registered only in this
// test build is listed, made, accepted in a scene's [backends.NAME] table and run by the run layer,
// with its thread-safety fact obeyed; an unknown [backends.NAME] table is the registry's error
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <mutex>

#include "core/run/fake_backend.hpp"
#include "error.hpp"
#include "registry.hpp"
#include "run/run_jobs.hpp"
#include "scene/scene_builder.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

namespace {

std::atomic<int> alive{0}, most_alive{0};

/// the fake ballistic backend, counting how many exist at once
class CountedBackend : public testing::FakeBackend {
public:
    CountedBackend() {
        const int k = ++alive;
        int m = most_alive.load();
        while (k > m && !most_alive.compare_exchange_weak(m, k)) {}
    }
    ~CountedBackend() override { --alive; }
    std::string name() const override { return "double"; }
};

/// the double's one registry line (in the test build only)
void register_double() {
    static std::once_flag once;
    std::call_once(once, [] {
        BackendInfo info;
        info.name = "double";
        info.description = "test double: a point mass in ballistic flight";
        info.solver = "none (no contact)";
        info.thread_safe = false;
        info.make = [] { return std::make_unique<CountedBackend>(); };
        register_backend(info);
    });
}

const char* kScene = R"(
[run]
duration = 0.05
dt = 1e-3
output_interval = 0.01
[contact]
kn = 3e7
ks = 3e7
friction = 0.6
[materials.stone]
density = 2600.0
young = 30e9
poisson = 0.2
[blocks.A]
material = "stone"
size = [1.0, 1.0, 1.0]
position = [0.0, 0.0, 5.0]
)";

}  // namespace

TEST_CASE("registry: a test double is listed, made and named in a scene's backend table", "[registry]") {
    register_double();
    const auto& all = available_backends();
    CHECK(std::any_of(all.begin(), all.end(), [](const BackendInfo& b) { return b.name == "double"; }));
    CHECK(make_backend("double")->name() == "double");
    CHECK_THROWS_WITH(register_backend(find_backend(all, "double")), Catch::Contains("registered already"));

    Scene s = parse_scene(std::string(kScene) + "[backends.double]\nflag = true\n", "double.toml");
    CHECK_NOTHROW(check_backend_tables(s, "double.toml"));
    s = parse_scene(std::string(kScene) + "[backends.physx]\niterations = 10\n", "bad.toml");
    CHECK_THROWS_WITH(check_backend_tables(s, "bad.toml"),
                      Catch::Contains("bad.toml:19: backends.physx: unknown backend (available: dem") &&
                          Catch::Contains("double)"));
    s = parse_scene(std::string(kScene) + "[backends.physx]\n", "bad.toml");
    CHECK_THROWS_WITH(check_backend_tables(s, "bad.toml"), Catch::StartsWith("bad.toml: backends.physx: unknown backend"));
}

TEST_CASE("registry: the run layer runs the double, never two at once (it says it is not thread-safe)", "[registry]") {
    register_double();
    const Scene scene = parse_scene(kScene, "double.toml");
    std::vector<RunSpec> jobs(6);
    for (auto& j : jobs) {
        j.scene = &scene;
        j.backend = "double";
    }
    JobsOptions options;
    options.jobs = 2;
    options.quiet = true;
    most_alive = 0;
    std::mutex m;
    int completed = 0;
    run_jobs(jobs, available_backends(), options, [&](size_t, JobResult& r) {
        std::lock_guard<std::mutex> lock(m);
        completed += r.outcome == Outcome::completed;
        // free fall from z = 5 m: z = 5 − g t²/2 at t = 0.05 s (the double is exact)
        CHECK(r.result.samples.back().blocks[0].position.z() == Approx(5.0 - 0.5 * 9.81 * 0.05 * 0.05).epsilon(1e-12));
    });
    CHECK(completed == 6);
    CHECK(most_alive.load() == 1);
}
