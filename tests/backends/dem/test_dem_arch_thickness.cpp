// Semicircular arches of 25 voussoirs at 1.1x and 0.93x the limit-analysis minimum thickness
// (compare/analytic): the thick one stands, the thin one collapses. The shipped scenes are the
// generator's output: `cairn make arch` with the options in their header (tests/app/test_make_command.cpp
// reruns it), whose geometry is checked here against core/scene/arch_builder.
#include <catch2/catch.hpp>

#include <string>

#include "analytic/arch_thrust.hpp"
#include "cases/case_analysis.hpp"
#include "dem_test_util.hpp"
#include "scene/arch_builder.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

namespace {

constexpr int kVoussoirs = 25;
constexpr double kRadius = 2.0;   // m, centreline
constexpr double kDepth = 0.5;    // m

struct ArchCase {
    const char* file;
    double factor;    // of the minimum thickness
    bool stands;
    double duration;  // s
};
const ArchCase kThick{"arch_thick", 1.1, true, 0.4};
const ArchCase kThin{"arch_thin", 0.93, false, 1.0};

ArchSpec spec(const ArchCase& c) {
    return {kVoussoirs, kRadius, c.factor * oracle::SemicircularArch{kVoussoirs}.minimum_thickness() * kRadius, kDepth};
}

std::string path(const ArchCase& c) { return std::string(CAIRN_SOURCE_DIR) + "/scenarios/structures/" + c.file + ".toml"; }

}  // namespace

TEST_CASE("the shipped arch scenes are the generator's output", "[dem][structures][arch]") {
    for (const auto& c : {kThick, kThin}) {
        INFO(path(c));
        const Scene s = load_scene(path(c), {});
        const ArchSpec a = spec(c);
        REQUIRE(s.blocks.size() == size_t(a.voussoirs + 2));
        // the file's t/R is the factor times the minimum to 10 digits: corners within 1e-8 m
        for (const BlockDef& b : s.blocks) {
            if (b.fixed) continue;
            const Corners want = arch_voussoir(a, std::stoi(b.name.substr(1)) - 1);   // V1 … VN
            for (size_t k = 0; k < 8; ++k) CHECK((b.position + b.orientation * b.corners[k] - want[k]).norm() < 1e-8);
        }
        REQUIRE(s.reference);
        CHECK(s.reference->values.at("stands") == (c.stands ? 1.0 : 0.0));
    }
}

// Both arches on the overlap contact at kn = 1e11 (the scene explains why so stiff; at 1e9 and
// 1e10 the thick one collapses with its energy closed).
TEST_CASE("a 25-voussoir arch 10 % thicker than the limit-analysis minimum stands", "[dem][structures][arch]") {
    const Scene s = load_scene(path(kThick), {});
    auto b = test::build_dem(s);
    std::vector<Sample> samples;
    int k = 0;
    const bool ok = test::run_dem(*b, s.run.duration, [&](const Sample& x) {
        if (k++ % 40 == 0) samples.push_back(x);
    });
    CHECK(ok);
    const auto r = cases::analyse_case(s, samples, {true});
    for (const auto& m : r.metrics) {
        INFO(m.name << ": " << m.value << " (bound " << m.reference << " + " << m.tolerance << ")");
        CHECK(m.pass());
    }
}

TEST_CASE("a 25-voussoir arch 7 % thinner than the limit-analysis minimum collapses", "[dem][structures][arch]") {
    const Scene s = load_scene(path(kThin), {});
    auto b = test::build_dem(s);
    std::vector<Sample> samples;
    int k = 0;
    test::run_dem(*b, s.run.duration, [&](const Sample& x) {
        if (k++ % 40 == 0) samples.push_back(x);
    });
    REQUIRE(samples.size() > 3);
    CHECK(samples.back().t == Approx(s.run.duration).margin(0.01));   // ran to the end, no blow-up
    const auto r = cases::analyse_case(s, samples, {true});
    for (const auto& m : r.metrics) {
        INFO(m.name << ": " << m.value << " (bound " << m.reference << ")");
        CHECK(m.pass());
    }
}
