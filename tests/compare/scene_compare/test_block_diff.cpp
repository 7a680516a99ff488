// block histories and their differences on samples whose answers are known in closed form
#include <catch2/catch.hpp>

#include <cmath>

#include "scene_compare/block_diff.hpp"
#include "scene_compare/variants.hpp"
#include "support/backend_facts.hpp"

using namespace cairn;
using namespace cairn::scene_compare;

namespace {

/// one free block turning about z at `omega` rad/s, moving along x at `v` m/s from x0, every 0.01 s
std::vector<Sample> spinning(double omega, double v, double x0, int n) {
    std::vector<Sample> out;
    for (int i = 0; i < n; ++i) {
        Sample s;
        s.t = 0.01 * i;
        BlockState b;
        b.position = Vec3(x0 + v * s.t, 0.0, 0.0);
        b.orientation = Quat(Eigen::AngleAxisd(0.3 + omega * s.t, Vec3::UnitY()));   // 0.3 rad at t = 0
        b.velocity = Vec3(v, 0.0, 0.0);
        s.blocks.push_back(b);
        out.push_back(s);
    }
    return out;
}

}  // namespace

TEST_CASE("rotation angle is measured from the orientation at t = 0", "[scene_compare]") {
    const auto h = block_history(spinning(0.5, 0.0, 0.0, 101), 0);
    REQUIRE(h.t.size() == 101);
    // angle = ω t exactly (the 0.3 rad at t = 0 is not counted); 1e-12 rad: rounding only
    for (size_t i = 0; i < h.t.size(); ++i) CHECK(h.angle[i] == Approx(0.5 * h.t[i]).margin(1e-12));
}

TEST_CASE("a constant offset gives that RMS and diverges at once, a linear drift diverges when it passes the threshold",
          "[scene_compare]") {
    DivergenceThresholds th;
    th.position = 0.004;   // m
    th.angle = 0.01;       // rad
    const auto base = block_history(spinning(0.0, 0.0, 0.0, 101), 0);
    // offset of 0.01 m: RMS and peak are 0.01 m, diverged at t = 0
    const auto off = block_diff(block_history(spinning(0.0, 0.0, 0.01, 101), 0), base, th);
    CHECK(off.position_rms == Approx(0.01).epsilon(1e-12));
    CHECK(off.position_peak == Approx(0.01).epsilon(1e-12));
    CHECK(off.position_diverged == 0.0);
    CHECK(std::isnan(off.angle_diverged));
    // drift at 0.1 m/s: distance 0.1 t passes 0.004 m after t = 0.04 s, so first at the sample t = 0.05 s;
    // RMS over t = 0 … 1 s sampled every 0.01 s is 0.1·sqrt(Σ t²/101)
    const auto drift = block_diff(block_history(spinning(0.0, 0.1, 0.0, 101), 0), base, th);
    CHECK(drift.position_diverged == Approx(0.05).margin(1e-12));
    double s2 = 0.0;
    for (int i = 0; i <= 100; ++i) s2 += (0.001 * i) * (0.001 * i);
    CHECK(drift.position_rms == Approx(std::sqrt(s2 / 101.0)).epsilon(1e-12));
    CHECK(drift.speed_rms == Approx(0.1).epsilon(1e-12));
    // turning at 0.5 rad/s against a still block: 0.5 t passes 0.01 rad after t = 0.02 s
    const auto turn = block_diff(block_history(spinning(0.5, 0.0, 0.0, 101), 0), base, th);
    CHECK(turn.angle_diverged == Approx(0.03).margin(1e-12));
    CHECK(turn.angle_peak == Approx(0.5).epsilon(1e-12));
    CHECK(turn.compared_until == Approx(1.0).margin(1e-12));
}

TEST_CASE("a scene without a reference runs every variant, and --model filters the block models", "[scene_compare]") {
    Scene s;
    const std::vector<BackendInfo> engines = {test::penalty_engine("dem"), test::rigid_engine("bullet"),
                                              test::rigid_engine("siconos", false)};
    const auto all = compare_variants(s, engines, "both");
    std::vector<std::string> names;
    for (const auto& v : all) names.push_back(v.name);
    // an engine with no spring stand-in (no penalty stiffness in its capability row) has no matched variant
    CHECK(names == std::vector<std::string>{"dem-rigid", "dem-deformable", "bullet-rigid", "bullet-matched", "siconos-rigid"});
    CHECK(compare_variants(s, engines, "deformable").size() == 1);
    CHECK(compare_variants(s, engines, "rigid").size() == 4);
}

TEST_CASE("compliance disagreement names the dem variants far from the rigid engines' median rotation",
          "[scene_compare]") {
    using scene_compare::VariantPeak;
    // the drum column under a 0.35 g pulse (docs/dem.md): dem overturns, the rigid engines rock
    const std::vector<VariantPeak> column{{"dem-rigid", true, false, 3.136},   {"dem-deformable", true, false, 3.127},
                                          {"bullet-rigid", false, true, 0.1124}, {"bullet-matched", false, false, 0.1295},
                                          {"ode-rigid", false, true, 0.1131},    {"mujoco-rigid", false, true, 0.1133}};
    const std::string text = scene_compare::compliance_disagreement(column);
    CHECK(text == "dem-rigid 3.14 rad, dem-deformable 3.13 rad against the rigid-contact engines' 0.113 rad (median)");
    // within 0.05 rad (or half the median) it is agreement; without a rigid-contact variant, no comparison
    CHECK(scene_compare::compliance_disagreement({{"dem-rigid", true, false, 0.16}, {"ode-rigid", false, true, 0.113}}).empty());
    CHECK_FALSE(scene_compare::compliance_disagreement({{"dem-rigid", true, false, 0.17}, {"ode-rigid", false, true, 0.113}}).empty());
    CHECK(scene_compare::compliance_disagreement({{"dem-rigid", true, false, 3.1}, {"ode-matched", false, false, 0.1}}).empty());
}

TEST_CASE("a report that cannot draw every block draws those that moved most, in the scene's order",
          "[scene_compare]") {
    // five blocks, two variants: block 3 moved most in one variant only, 0 and 4 tie on displacement
    // and 4 turned more, 1 and 2 hardly moved
    const std::vector<std::vector<BlockPeaks>> peaks{
        {{0.5, 0.1, 1.0}, {0.001, 0.0, 0.0}, {0.002, 0.0, 0.0}, {0.01, 0.0, 0.0}, {0.5, 0.3, 1.0}},
        {{0.4, 0.1, 1.0}, {0.001, 0.0, 0.0}, {0.003, 0.0, 0.0}, {2.0, 1.0, 3.0}, {0.2, 0.1, 1.0}}};
    CHECK(blocks_to_show(peaks, 5, 2) == std::vector<size_t>{3, 4});
    CHECK(blocks_to_show(peaks, 5, 3) == std::vector<size_t>{0, 3, 4});
    CHECK(blocks_to_show(peaks, 5, 4) == std::vector<size_t>{0, 2, 3, 4});
    // all fit: every block, in order; none asked for: none
    CHECK(blocks_to_show(peaks, 5, 5) == std::vector<size_t>{0, 1, 2, 3, 4});
    CHECK(blocks_to_show(peaks, 5, 0).empty());
    // a variant that failed before its first sample has no peaks: the others decide
    CHECK(blocks_to_show({{}, peaks[1]}, 5, 1) == std::vector<size_t>{3});
}
