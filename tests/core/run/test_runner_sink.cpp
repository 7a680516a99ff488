// run_scene() with a sink: the samples handed over as they are taken, running summaries in place of
// the vector, and a stop asked for from outside (SIGINT/SIGTERM) ending the run at a step boundary
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "fake_backend.hpp"
#include "run/runner.hpp"
#include "run/stop.hpp"

using namespace cairn;
using namespace cairn::testing;
using Catch::Matchers::Contains;

namespace {

/// records the calls it gets, and can ask for a stop after a number of samples
struct RecordingSink : SampleSink {
    std::vector<std::string> calls;
    std::vector<Sample> samples;
    long long stop_after = -1;   ///< request_stop() once this many samples arrived
    void begin(const Scene&, const RunResult& run) override {
        calls.push_back("begin dt=" + std::to_string(run.dt));
    }
    void sample(const Sample& s) override {
        calls.push_back("sample");
        samples.push_back(s);
        if (stop_after >= 0 && (long long)samples.size() == stop_after) request_stop();
    }
    void end(const RunResult& run) override {
        calls.push_back("end steps=" + std::to_string(run.steps));
    }
};

}  // namespace

TEST_CASE("run_scene hands every sample to the sink between begin and end", "[runner]") {
    const Scene scene = ballistic_scene();
    FakeBackend a, b;
    RecordingSink sink;
    const RunResult streamed = run_scene(a, scene, {}, sink);
    const RunResult collected = run_scene(b, scene, {});
    CHECK(streamed.samples.empty());   // a sink run keeps nothing in memory
    REQUIRE(sink.samples.size() == collected.samples.size());
    REQUIRE(sink.calls.size() == sink.samples.size() + 2);
    CHECK(sink.calls.front() == "begin dt=" + std::to_string(1e-3));
    CHECK(sink.calls.back() == "end steps=100");
    for (size_t i = 0; i < sink.samples.size(); ++i) {
        CHECK(sink.samples[i].t == collected.samples[i].t);
        CHECK(sink.samples[i].blocks[0].position == collected.samples[i].blocks[0].position);
    }
    // the running summary is what the vector held
    CHECK(streamed.sample_count == 11);
    CHECK(streamed.initial_total == collected.samples.front().energy.total());
    CHECK(streamed.final_time == collected.samples.back().t);
    CHECK(streamed.final_energy.kinetic == collected.samples.back().energy.kinetic);
    CHECK(streamed.max_balance_error == collected.max_balance_error);
}

TEST_CASE("the drift and growth checks work from running summaries", "[runner]") {
    Scene scene = ballistic_scene();
    SECTION("slow drift is flagged, the run completes") {
        // 2 J/s over 0.1 s: 0.2 J against a scale of at least 1 J, above the 1 % drift bound
        FakeBackend backend(Faults{-1, -1, 0.0, 2.0});
        RecordingSink sink;
        const RunResult r = run_scene(backend, scene, {}, sink);
        CHECK(r.status == RunStatus::completed);
        CHECK(r.energy_drift);
        CHECK(r.final_energy.dissipated == Approx(0.2));
    }
    SECTION("growth without a source stops the run") {
        FakeBackend backend(Faults{-1, -1, 0.5, 0.0});
        RecordingSink sink;
        const RunResult r = run_scene(backend, scene, {}, sink);
        CHECK(r.status == RunStatus::unstable);
        CHECK_THAT(r.message, Contains("energy growing without a source"));
        CHECK(r.sample_count == (long long)sink.samples.size());
        CHECK(sink.calls.back().rfind("end", 0) == 0);
    }
}

TEST_CASE("a stop request ends the run at the next step with status interrupted", "[runner]") {
    const Scene scene = ballistic_scene();   // 100 steps of 1 ms, a sample every 10
    FakeBackend backend;
    RecordingSink sink;
    sink.stop_after = 3;   // asked during the sample at step 20
    const RunResult r = run_scene(backend, scene, {}, sink);
    clear_stop();
    CHECK(r.status == RunStatus::interrupted);
    CHECK_THAT(r.message, Contains("interrupted at t = 0.02 s") && Contains("20 of 100 steps"));
    CHECK(r.steps == 20);
    // the state at the stop is the last sample: already taken at step 20, not repeated
    REQUIRE(sink.samples.size() == 3);
    CHECK(sink.samples.back().t == Approx(0.02));
    CHECK(sink.calls.back() == "end steps=20");

}

TEST_CASE("a stop between output steps ends the trajectory with the state reached", "[runner]") {
    /// asks for a stop (as the signal handler does) right after step 15, which is not sampled
    struct StoppingBackend : FakeBackend {
        long long n = 0;
        StepStatus step() override {
            const StepStatus st = FakeBackend::step();
            if (++n == 15) request_stop();
            return st;
        }
    };
    const Scene scene = ballistic_scene();
    StoppingBackend backend;
    RecordingSink sink;
    const RunResult r = run_scene(backend, scene, {}, sink);
    clear_stop();
    CHECK(r.status == RunStatus::interrupted);
    CHECK(r.steps == 15);
    REQUIRE(sink.samples.size() == 3);   // steps 0, 10 and the stop at 15
    CHECK(sink.samples.back().t == Approx(0.015));
    CHECK(r.final_time == sink.samples.back().t);
}

TEST_CASE("a stop requested before the run starts keeps only the initial state", "[runner]") {
    const Scene scene = ballistic_scene();
    FakeBackend backend;
    RecordingSink sink;
    request_stop();
    const RunResult r = run_scene(backend, scene, {}, sink);
    clear_stop();
    CHECK(r.status == RunStatus::interrupted);
    CHECK(r.steps == 0);
    REQUIRE(sink.samples.size() == 1);
    CHECK(sink.samples[0].t == 0.0);
}
