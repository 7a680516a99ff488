// Semicircular arches of 25 voussoirs at 1.1x and 0.93x the limit-analysis minimum thickness
// (compare/analytic): the thick one stands, the thin one collapses. The shipped scenes are the
// generator's output (core/scene/arch_builder); `test_dem "[.write_arch_scenes]"` rewrites them.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
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

/// the whole scene file
std::string scene_text(const ArchCase& c) {
    const ArchSpec a = spec(c);
    const double tr = a.thickness / a.radius;
    std::ostringstream o;
    o.precision(6);
    o << "# A semicircular stone arch of " << a.voussoirs << " voussoirs with radial joints (centreline radius "
      << a.radius << " m, " << a.depth << " m deep) on two fixed abutments under its own weight, at " << c.factor
      << "x the\n# limit-analysis minimum thickness of a " << a.voussoirs << "-voussoir arch, t/R = "
      << oracle::SemicircularArch{a.voussoirs}.minimum_thickness()
      << " (compare/analytic; joints everywhere: 0.1075):\n# t = " << a.thickness << " m, t/R = " << tr << ". "
      << (c.stands ? "A thrust line fits: it must stand, settling only by the joints' elastic closure."
                   : "No thrust line fits: a five-hinge mechanism forms and it collapses.")
      << "\n# Written by the arch generator (core/scene/arch_builder), see tests/backends/dem/test_dem_arch_thickness.cpp.\n"
      << "description = \"Semicircular arch of " << a.voussoirs << " voussoirs at " << c.factor
      << "x the minimum thickness: " << (c.stands ? "stands" : "collapses") << "\"\n\n"
      << "[run]\nduration = " << c.duration << "              # s\noutput_interval = 0.005     # s\n\n"
      << "[materials.stone]\ndensity = 2600              # kg/m³\nyoung = 30e9                # Pa\npoisson = 0.2\n\n"
      << "[contact]\n"
      << "scheme = \"overlap\"          # the penalty integrated over each joint (docs/dem.md)\n"
      << "subdivision = 1             # one shear sub-contact per joint face: the joints do not slide\n"
      << "# stiff joints: near its limit an arch stands only if its joints hinge little. A joint whose\n"
      << "# thrust N passes e from its edge needs the rotation 2N/(kn·D·(3e)²) (D = 0.5 m); at 1.1x\n"
      << "# the minimum e is about 1 cm, and at kn = 1e9 the hinges turn ~0.01 rad, moving the arch\n"
      << "# by more than that margin: it collapses (measured, also at 1e10). At 1e11, ~1e-4 rad.\n"
      << "kn = 1e11                   # N/m³\nks = 1e11                   # N/m³\n"
      << "friction = 0.8              # no sliding: the thrust stays well inside the friction cone\n"
      << "damping_ratio = 0.1         # ζ: the joints' elastic closure settles\n\n"
      << arch_blocks_toml(a, "stone")
      << "[probes.crown]              # middle of the keystone's intrados\nblock = \"V" << (a.voussoirs + 1) / 2
      << "\"\npoint = [0.0, 0.0, " << a.radius - 0.5 * a.thickness << "]\n\n"
      << "[reference]\nkind = \"arch\"\nblock = \"V" << (a.voussoirs + 1) / 2 << "\"\nstands = " << (c.stands ? 1 : 0)
      << "\nthickness = " << a.thickness << "      # m\n";
    return o.str();
}

std::string read(const std::string& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

}  // namespace

TEST_CASE("write the shipped arch scenes", "[.write_arch_scenes]") {
    for (const auto& c : {kThick, kThin}) std::ofstream(path(c)) << scene_text(c);
}

TEST_CASE("the shipped arch scenes are the generator's output", "[dem][structures][arch]") {
    for (const auto& c : {kThick, kThin}) {
        INFO(path(c));
        CHECK(read(path(c)) == scene_text(c));
        const Scene s = load_scene(path(c), {});
        const ArchSpec a = spec(c);
        REQUIRE(s.blocks.size() == size_t(a.voussoirs + 2));
        CHECK((s.blocks[0].corners[1] - arch_voussoir(a, 0)[1]).norm() < 1e-8);
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
