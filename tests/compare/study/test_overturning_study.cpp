// the overturning and record studies: their scenes and helpers, and end to end on Bullet
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "error.hpp"
#include "study/overturning_study.hpp"
#include "study/record_study.hpp"

using namespace cairn;
using namespace cairn::study;
namespace fs = std::filesystem;

namespace {

OverturningSetup slender() {
    OverturningSetup s;
    s.scene_text = block_scene_text(0.2, 0.7, 1.0);
    s.scene_source = "<test>";
    s.b = 0.1;
    s.h = 0.5;
    s.levels = default_levels();
    s.ratios = default_ratios();
    return s;
}

/// run cairn with `args` into a fresh scratch directory; returns it
fs::path run_cairn(const std::string& name, const std::string& args) {
    const fs::path exe = fs::path(CAIRN_BINARY_DIR) / "app" / "cairn";
    if (!fs::exists(exe)) FAIL("build the cairn target first: " << exe);
    const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "study" / (name + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string cmd = exe.string() + " " + args + " -q --out '" + (dir / "out").string() + "' > '" +
                            (dir / "log.txt").string() + "' 2>&1";
    if (std::system(cmd.c_str()) != 0) FAIL("cairn " << args << " failed; see " << (dir / "log.txt"));
    return dir / "out";
}

/// the cells of the CSV row whose first two cells are `a` and `b`
std::vector<std::string> csv_row(const fs::path& path, const std::string& a, const std::string& b) {
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::istringstream ls(line);
        for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
        if (cells.size() >= 2 && cells[0] == a && cells[1] == b) return cells;
    }
    FAIL("no row " << a << "," << b << " in " << path);
    return {};
}

}  // namespace

TEST_CASE("overturning: the generated block scene parses and the study finds its block", "[overturning]") {
    const Scene scene = parse_scene(block_scene_text(0.2, 0.7, 1.0), "<test>");
    const auto rb = rocking_block_of(scene);
    CHECK(scene.blocks.at(size_t(rb.block)).name == "A");
    CHECK(rb.b == Approx(0.1).epsilon(1e-12));
    CHECK(rb.h == Approx(0.5).epsilon(1e-12));
    CHECK(rb.g == Approx(9.81).epsilon(1e-12));
    CHECK_THROWS_AS(block_scene_text(0.0, 0.7, 1.0), Error);
}

TEST_CASE("overturning: the generated block gives the in-house engine hitting points on the two bottom edges only", "[overturning]") {
    // Housner's impact is a push at the new corner alone: the paper scheme puts ceil(W / spacing) + 1
    // rows across the width, so a spacing of W leaves the two edges; stiff and damped near critical
    for (const double w : {0.2, 0.3, 0.73}) {
        const Scene scene = parse_scene(block_scene_text(w, 0.7, 1.0), "<test>");
        CHECK(scene.contact.scheme == ContactScheme::paper);
        CHECK(scene.contact.grid_spacing == Approx(w).epsilon(1e-12));
        double x0 = 1e300, x1 = -1e300;
        for (const auto& c : scene.blocks.at(0).corners) x0 = std::min(x0, c.x()), x1 = std::max(x1, c.x());
        CHECK(std::ceil((x1 - x0) / scene.contact.grid_spacing) + 1.0 == 2.0);   // rows across the width
        CHECK(scene.contact.kn == Approx(3e10));
        CHECK(scene.contact.damping_rule == ContactDampingRule::ratio);
        CHECK(scene.contact.damping == Approx(0.6));
    }
}

TEST_CASE("overturning: a scene with a tilted block or two free blocks is refused", "[overturning]") {
    const std::string text = block_scene_text(0.2, 0.7, 1.0);
    CHECK_THROWS_AS(rocking_block_of(parse_scene(text, "<test>", {{"blocks.A.orientation", "{axis = [0.0, 1.0, 0.0], angle = 0.1}"}})),
                    Error);
    CHECK_THROWS_AS(rocking_block_of(parse_scene(text, "<test>", {{"blocks.B.fixed", "false"}})), Error);
}

TEST_CASE("overturning: a pulse scene carries the pulse as its ground motion", "[overturning]") {
    const OverturningSetup s = slender();
    const auto o = setup_oracle(s);
    for (const auto shape : {oracle::PulseShape::sine, oracle::PulseShape::cosine, oracle::PulseShape::ricker}) {
        OverturningSetup t = s;
        t.pulse = shape;
        const oracle::Pulse pulse = point_pulse(t, 5.0, 3.0);
        CHECK(pulse.amplitude == Approx(3.0 * 9.81 * std::tan(o.alpha())).epsilon(1e-12));
        CHECK(pulse.omega == Approx(5.0 * o.p()).epsilon(1e-12));
        const Scene scene = pulse_scene(t, pulse);
        REQUIRE(scene.ground_motion);
        REQUIRE(scene.ground_motion->components.size() == 1);
        CHECK(scene.run.duration == Approx(pulse.duration() + t.tail).epsilon(1e-9));
        // 800 linear pieces per pulse: within (2π/800)²/8 of a_p for the sine (ricker: its own
        // curvature, at most 1.5 ω² a_p, over duration/800 = 0.02/ω: 7.5e-5 a_p)
        for (int i = 1; i < 50; ++i) {
            const double tt = pulse.duration() * (i + 0.37) / 50.0;
            CHECK(std::abs(scene.ground_motion->components.at(0).acceleration.at(tt) - pulse.at(tt)) < 1e-4 * pulse.amplitude);
        }
    }
}

TEST_CASE("overturning: the grid job list is backend x frequency x amplitude", "[overturning]") {
    OverturningSetup s = slender();
    s.backends = {"bullet", "ode"};
    const auto jobs = grid_jobs(s);
    REQUIRE(jobs.size() == 2 * s.ratios.size() * s.levels.size());
    CHECK(jobs.front().method == "bullet");
    CHECK(jobs.back().method == "ode");
    CHECK(jobs[1].level == s.levels[1]);
    CHECK(jobs[s.levels.size()].ratio == s.ratios[1]);
}

TEST_CASE("record: histories part at the first difference beyond the limit", "[overturning]") {
    const std::vector<double> t{0.0, 1.0, 2.0, 3.0};
    CHECK(parting_time(t, {0, 0, 0, 0}, {0, 0.01, 0.02, 0.2}, 0.1) == 3.0);
    CHECK(std::isnan(parting_time(t, {0, 0, 0, 0}, {0, 0.01, 0.02, 0.05}, 0.1)));
    CHECK(parting_time(t, {0, NAN, 0, 0}, {0, 0, 0, 0}, 0.1) == 1.0);   // a failed run parts
}

TEST_CASE("study: Bullet's minimum overturning amplitude at w_p/p = 5 is within 1 % of the oracle's", "[study][slow]") {
    // bracket [2, 2.75] g tan a, 6 bisections: 0.012 g tan a wide, 0.45 % of the oracle's 2.578; Bullet's
    // inelastic impact matches Housner's r closely, measured +0.2 % on the full grid
    const fs::path out = run_cairn("overturning", "study overturning --block 0.2,1.0,0.7 --backends bullet --ratios 5 "
                                                  "--levels 2,2.75 --bisect 6");
    const auto oracle = csv_row(out / "overturning_boundary.csv", "oracle", "5");
    const auto bullet = csv_row(out / "overturning_boundary.csv", "bullet", "5");
    const double a_oracle = std::stod(oracle[4]), a_bullet = std::stod(bullet[4]);
    CHECK(a_oracle == Approx(2.578).epsilon(1e-3));   // the oracle's own bisection, to 40 halvings
    CHECK(std::abs(a_bullet / a_oracle - 1.0) < 0.01);
    CHECK(fs::exists(out / "overturning.md"));
    CHECK(fs::exists(out / "overturning.html"));
}

TEST_CASE("study: dem on the study's block keeps Housner's share of the rotation at each impact", "[study][slow]") {
    // the slender block released at 0.8 alpha rocks freely; from each amplitude theta_n the energy at
    // impact is m g R (cos(alpha - theta_n) - cos alpha), so sqrt of the ratio of two successive ones is
    // the angular-velocity ratio of the impact between them, against Housner's r = 1 - 1.5 sin^2 alpha
    const double alpha = std::atan(0.2), r_housner = 1.0 - 1.5 * std::pow(std::sin(alpha), 2);
    const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "study" / ("impact_scene_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "block.toml") << block_scene_text(0.2, 0.7, 1.0);
    const fs::path out = run_cairn("impact", "run '" + (dir / "block.toml").string() + "' -b dem --set run.duration=2.6 " +
                                                 "--set run.output_interval=0.0005 --set blocks.A.pivot=[0.1,0.0,0.0] " +
                                                 "--set 'blocks.A.orientation={axis = [0.0, 1.0, 0.0], angle = " +
                                                 std::to_string(0.8 * alpha) + "}'");
    std::ifstream in(out / "trajectory.csv");
    std::string line;
    std::getline(in, line);
    std::vector<std::string> head;
    for (std::istringstream ls(line); std::getline(ls, line, ',');) head.push_back(line);
    const auto col = [&](const std::string& name) { return size_t(std::find(head.begin(), head.end(), name) - head.begin()); };
    const size_t qw = col("A.qw [-]"), qy = col("A.qy [-]");
    REQUIRE(qy < head.size());
    std::vector<double> amplitudes{0.0};
    double sign = 1.0;
    while (std::getline(in, line)) {
        std::vector<double> v;
        std::istringstream ls(line);
        for (std::string c; std::getline(ls, c, ',');) v.push_back(std::stod(c));
        const double theta = 2.0 * std::atan2(v.at(qy), v.at(qw));
        // an impact: theta crosses 0 (past 1e-3 alpha, so that a touch that comes back is no impact)
        if (theta * sign < -1e-3 * alpha) sign = -sign, amplitudes.push_back(0.0);
        amplitudes.back() = std::max(amplitudes.back(), std::abs(theta));
    }
    REQUIRE(amplitudes.size() >= 3);   // two impacts within the run (Housner's first at 0.60 s)
    CHECK(amplitudes[0] == Approx(0.8 * alpha).epsilon(1e-3));
    for (size_t i = 0; i + 1 < 3; ++i) {
        const double e0 = std::cos(alpha - amplitudes[i]) - std::cos(alpha), e1 = std::cos(alpha - amplitudes[i + 1]) - std::cos(alpha);
        const double r = std::sqrt(e1 / e0);
        INFO("impact " << i + 1 << ": r = " << r << " against Housner's " << r_housner);
        // 0.3 %: the penalty impact lasts a finite time in which the old edge's row still pushes
        // (measured +0.08 %); a third row across the width keeps 1.3 % more (0.955), which this catches
        CHECK(std::abs(r / r_housner - 1.0) < 3e-3);
    }
}

TEST_CASE("study: dem's minimum overturning amplitude at w_p/p = 5 is within 0.5 % of the oracle's", "[study][slow]") {
    // bracket [2, 2.75] g tan a, 7 bisections: 0.0059 g tan a wide, the midpoint within 0.12 % of where
    // dem flips; its contact on the study's block (edge rows, kn 3e10, zeta 0.6) measured -0.11 %
    const fs::path out = run_cairn("overturning_dem", "study overturning --block 0.2,1.0,0.7 --backends dem --ratios 5 "
                                                      "--levels 2,2.75 --bisect 7");
    const double a_oracle = std::stod(csv_row(out / "overturning_boundary.csv", "oracle", "5")[4]);
    const double a_dem = std::stod(csv_row(out / "overturning_boundary.csv", "dem", "5")[4]);
    CHECK(std::abs(a_dem / a_oracle - 1.0) < 0.005);
}

TEST_CASE("study: under El Centro Bullet follows the oracle through the first rocking cycles", "[study][slow]") {
    // the 0.3 x 1.5 m column uplifts at about 2 s; Bullet parts from the oracle (5 % of alpha) after
    // 3.3 s, about when the oracle parts from itself with r or the record 1 % larger (3.4-3.8 s)
    const fs::path out = run_cairn("record", "study record --block 0.3,1.5,0.3 --duration 5 --backends bullet");
    std::ifstream in(out / "record.md");
    std::stringstream text;
    text << in.rdbuf();
    const std::string md = text.str();
    const auto row = md.find("| bullet | ");
    REQUIRE(row != std::string::npos);
    const double parting = std::stod(md.substr(row + 11, 6));
    CHECK(parting > 2.5);
    CHECK(md.find("| oracle r+1% | ") != std::string::npos);
}

TEST_CASE("overturning: bad options and scenes are refused with exit 2 and nothing written", "[overturning]") {
    const fs::path exe = fs::path(CAIRN_BINARY_DIR) / "app" / "cairn";
    if (!fs::exists(exe)) FAIL("build the cairn target first: " << exe);
    const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "study" / ("refused_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scenes = std::string(CAIRN_SOURCE_DIR) + "/scenarios/";
    const std::vector<std::pair<std::string, std::string>> cases{
        {"study overturning", "give a scene or --block"},
        {"study overturning --block 0.2,1.0 --pulse square", "unknown pulse shape 'square'"},
        {"study overturning --block 0.2,1.0 --grid 3y3", "--grid 3y3"},
        {"study overturning --block 0.2,1.0 --levels 3,2", "--levels"},
        {"study overturning --block 0.2,1.0 --backends nosuch", "--backends nosuch"},
        {"study overturning '" + scenes + "earthquake/column_elcentro.toml'", "the study applies its own pulses"},
        {"study overturning '" + scenes + "paper/rocking_slender.toml'", "blocks.A.orientation"},
        {"study record --block 0.2,1.0 --record /nonexistent.csv", "cannot open the ground-motion file"},
    };
    for (size_t i = 0; i < cases.size(); ++i) {
        const fs::path out = dir / ("out" + std::to_string(i)), log = dir / ("log" + std::to_string(i));
        const std::string cmd = exe.string() + " " + cases[i].first + " -q --out '" + out.string() + "' > '" +
                                log.string() + "' 2>&1";
        const int status = std::system(cmd.c_str());
        INFO(cases[i].first);
        REQUIRE(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 2);
        CHECK_FALSE(fs::exists(out));
        std::ifstream in(log);
        std::stringstream text;
        text << in.rdbuf();
        CHECK(text.str().find(cases[i].second) != std::string::npos);
    }
}
