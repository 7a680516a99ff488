// Pushover of the shipped column and wall scenes on dem: they overturn as one body at the a/g of
// the rigid limit analysis, plus the ramp's lag (compare/analytic), within 2 %.
#include <catch2/catch.hpp>

#include <string>

#include "cases/case_analysis.hpp"
#include "dem_test_util.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

namespace {

// run the shipped scene on dem, keeping a sample per output interval, and analyse it
cases::CaseAnalysis pushover(const std::string& name, bool& completed) {
    const Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/structures/" + name + ".toml", {});
    auto b = test::build_dem(s);
    const long long every = std::max(1LL, std::llround(s.run.output_interval / b->time_step()));
    std::vector<Sample> samples;
    long long k = 0;
    completed = test::run_dem(*b, s.run.duration, [&](const Sample& x) {
        if (k++ % every == 0) samples.push_back(x);
    });
    REQUIRE(samples.size() > 3);
    return cases::analyse_case(s, samples, {true});
}

void check_metrics(const cases::CaseAnalysis& r) {
    for (const auto& m : r.metrics) {
        INFO(m.name << ": " << m.value << " against " << m.reference << " (" << m.basis << ")");
        CHECK(m.pass());
    }
}

}  // namespace

TEST_CASE("a column of three drums overturns as one body at a/g = B/H plus the ramp's lag", "[dem][structures][pushover]") {
    bool completed = false;
    const auto r = pushover("column_pushover", completed);
    CHECK(completed);
    REQUIRE(!r.metrics.empty());
    // measured on the paper's node-to-face contact (0.1 m grid, 5 x 5 points a face): 0.2670
    // against 0.2708 (B/H = 0.2667 plus the ramp's 1.5 % lag): −1.4 %. The grid's edge row takes
    // the whole weight at B/2 once the joint opens, so the column behaves almost rigidly; the same
    // joint integrated exactly would lean and peak at 0.232 (Winkler, kn = 1e9), reported beside
    check_metrics(r);
}

// mayfail: the wall now has half-brick closers (every brick on its whole base) and the start of
// its run is stable with closed energy on both contact schemes (paper to 0.54 s, overlap to
// 0.15 s; the old wall stopped unstable at 0.40 s), but the 36 s ramp has not been run through.
// With penalty joints the wall leans and should tip below the rigid reference by the Winkler
// peak's deficit (docs/validation.md), so this verdict is still open
TEST_CASE("a running-bond wall tips out of plane at a/g = t/H plus the ramp's lag", "[dem][structures][pushover][!mayfail]") {
    bool completed = false;
    const auto r = pushover("wall_pushover", completed);
    CHECK(completed);
    check_metrics(r);
}
