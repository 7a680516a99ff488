// The run layer: jobs on the fake backend (ballistic flight, exact positions), their outcomes,
// files, repeats and refusals
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>

#include "error.hpp"
#include "fake_backend.hpp"
#include "geometry/hexahedron.hpp"
#include "run/run_jobs.hpp"
#include "scene/scene_builder.hpp"

using namespace cairn;
namespace fs = std::filesystem;

namespace {

Scene flight_scene() {
    Scene s;
    s.materials.push_back({"stone", 2600.0, 30e9, 0.2});
    add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 10), false);
    s.blocks[0].velocity = Vec3(1, 0, 0);
    s.run.duration = 0.1;
    s.run.dt = 1e-3;
    s.run.output_interval = 0.01;
    return s;
}

BackendInfo fake_info(const std::string& name, testing::Faults faults = {}) {
    BackendInfo b;
    b.name = name;
    b.make = [faults] { return std::make_unique<testing::FakeBackend>(faults); };
    return b;
}

}  // namespace

TEST_CASE("run jobs: outcomes, the first run's samples, a median of the repeats", "[run][jobs]") {
    const Scene scene = flight_scene();
    testing::Faults bad;
    bad.unstable_at_step = 20;
    const std::vector<BackendInfo> backends{fake_info("fake"), fake_info("shaky", bad)};
    std::vector<RunSpec> jobs(3);
    for (auto& j : jobs) j.scene = &scene;
    jobs[0].backend = "fake";
    jobs[0].repeats = 3;
    jobs[1].backend = "shaky";
    jobs[1].repeats = 3;
    jobs[2].backend = "nosuch";
    std::vector<JobResult> got(jobs.size());
    std::vector<int> calls(jobs.size(), 0);
    std::mutex m;
    JobsOptions options;
    options.quiet = true;
    run_jobs(jobs, backends, options, [&](size_t i, JobResult& r) {
        std::lock_guard<std::mutex> lock(m);
        ++calls[i];
        got[i] = std::move(r);
    });
    for (int c : calls) CHECK(c == 1);
    CHECK(got[0].outcome == Outcome::completed);
    CHECK(std::isfinite(got[0].median_wall));
    REQUIRE(got[0].result.samples.size() == 11);   // t = 0 and every 0.01 s to 0.1 s
    // free flight: x = v t exactly (the fake backend is analytic), within rounding
    CHECK(got[0].result.samples.back().blocks[0].position.x() == Approx(0.1).epsilon(1e-12));
    CHECK(got[1].outcome == Outcome::unstable);
    CHECK_THAT(got[1].message, Catch::Contains("contact spring overshoot"));
    CHECK(got[2].outcome == Outcome::refused);
    CHECK_THAT(got[2].message, Catch::Contains("unknown backend 'nosuch'"));
    CHECK(std::string(to_string(Outcome::input_error)) == "error");
}

TEST_CASE("run jobs write a run's files, an unstable run keeps a partial trajectory", "[run][jobs]") {
    const Scene scene = flight_scene();
    testing::Faults bad;
    bad.unstable_at_step = 20;
    const std::vector<BackendInfo> backends{fake_info("fake"), fake_info("shaky", bad)};
    const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "run_jobs";
    fs::remove_all(dir);
    std::vector<RunSpec> jobs(2);
    for (size_t i = 0; i < jobs.size(); ++i) {
        jobs[i].scene = &scene;
        jobs[i].backend = i == 0 ? "fake" : "shaky";
        jobs[i].out_dir = (dir / jobs[i].backend).string();
        jobs[i].keep_samples = false;
    }
    JobsOptions options;
    options.quiet = true;
    run_jobs(jobs, backends, options, [](size_t, JobResult& r) { CHECK(r.result.samples.empty()); });
    CHECK(fs::exists(dir / "fake" / "trajectory.csv"));
    CHECK(fs::exists(dir / "fake" / "run.json"));
    CHECK(fs::exists(dir / "shaky" / "trajectory.partial.csv"));
    CHECK_FALSE(fs::exists(dir / "shaky" / "trajectory.csv"));
    std::ifstream record(dir / "shaky" / "run.json");
    const std::string text((std::istreambuf_iterator<char>(record)), std::istreambuf_iterator<char>());
    CHECK_THAT(text, Catch::Contains("\"unstable\""));
}

TEST_CASE("run jobs resume: a job list run twice runs nothing the second time, with the same results", "[run][jobs]") {
    const Scene scene = flight_scene();
    Scene longer = flight_scene();
    longer.run.duration = 0.2;   // another scene text: another key
    testing::Faults bad;
    bad.unstable_at_step = 20;
    const std::vector<BackendInfo> backends{fake_info("fake"), fake_info("shaky", bad)};
    const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "run_jobs_resume";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::vector<RunSpec> jobs(3);
    jobs[0].scene = &scene, jobs[0].backend = "fake";
    jobs[1].scene = &longer, jobs[1].backend = "fake";
    jobs[2].scene = &scene, jobs[2].backend = "shaky";
    // the record a caller keeps: outcome and last x of the run
    auto run_list = [&](std::vector<JobResult>& got) {
        ResumeLog log((dir / "jobs.resume").string());
        JobsOptions options;
        options.quiet = true;
        options.resume = &log;
        std::mutex m;
        return run_jobs(jobs, backends, options, [&](size_t i, JobResult& r) {
            if (!r.resumed) r.record = message_number(r.result.samples.back().blocks[0].position.x(), 17);
            std::lock_guard<std::mutex> lock(m);
            got[i] = r;
        });
    };
    std::vector<JobResult> first(jobs.size()), second(jobs.size());
    CHECK(run_list(first) == 3);
    CHECK(run_list(second) == 0);
    for (size_t i = 0; i < jobs.size(); ++i) {
        CHECK_FALSE(first[i].resumed);
        CHECK(second[i].resumed);
        CHECK(second[i].outcome == first[i].outcome);
        CHECK(second[i].record == first[i].record);
    }
    CHECK(first[1].record != first[0].record);   // the longer flight went further: keys differ
    CHECK(second[2].outcome == Outcome::unstable);
    // another backend or contact mode is another job
    jobs[0].options.contact_mode = "matched";
    std::vector<JobResult> third(jobs.size());
    CHECK(run_list(third) == 1);
    CHECK_FALSE(third[0].resumed);
}
