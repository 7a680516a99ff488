// The refresh's pruning of the overlap scheme's candidates: what it leaves out never acts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "dem/world.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

TEST_CASE("the refresh leaves out only faces that never act: a collapsing stack is bit-identical", "[dem][contact]") {
    // a column of four blocks, each turned about z, on a base and a tumbling block thrown into it:
    // sliding,
    // rotation and new contacts between refreshes; once with the faces that cannot reach their
    // target left out at each refresh, once with every face whose box meets the target's
    Scene s = test::stone_scene(0.4);
    s.contact.scheme = ContactScheme::overlap;
    s.contact.kn = s.contact.ks = 1e9;
    s.run.contact_interval = 10;
    add_box(s, "base", Vec3(3, 3, 0.5), Vec3(0, 0, -0.25), true);
    for (int k = 0; k < 4; ++k)
        add_box(s, "c" + std::to_string(k), Vec3(0.4, 0.3, 0.25), Vec3(0.03 * k, 0.01 * k, 0.1255 + 0.2505 * k), false,
                Quat(Eigen::AngleAxisd(0.1 * k, Vec3::UnitZ())));
    add_box(s, "thrown", Vec3(0.3, 0.3, 0.3), Vec3(-0.6, 0.05, 0.7), false, Quat(Eigen::AngleAxisd(0.4, Vec3(1, 1, 1).normalized())));
    s.blocks.back().velocity = Vec3(2.0, 0, 0);
    s.blocks.back().angular_velocity = Vec3(0, 3, 1);
    double thrown_x = 0.0;
    auto run = [&](bool prune, size_t& fewest, size_t& most) {
        dem::World w(s, 0.01);
        w.prune_contacts(prune);
        w.start(2e-5);
        std::vector<Vec3> x;
        fewest = 1u << 30, most = 0;
        for (int i = 0; i < 30000; ++i) {
            const bool ok = w.step();
            INFO("step " << i << ": " << w.failure());
            REQUIRE(ok);
            if (i % 10 == 0) fewest = std::min(fewest, w.candidate_count()), most = std::max(most, w.candidate_count());
            for (const auto& b : w.blocks()) x.push_back(b.body.x), x.push_back(b.body.L);
        }
        thrown_x = w.blocks().back().body.x.x();
        x.push_back(Vec3(w.energy().contact, w.energy().dissipated, w.kinetic()));
        return x;
    };
    size_t pruned_lo, pruned_hi, all_lo, all_hi;
    const auto b = run(false, all_lo, all_hi), a = run(true, pruned_lo, pruned_hi);
    INFO("candidates pruned " << pruned_lo << "-" << pruned_hi << ", all " << all_lo << "-" << all_hi);
    CHECK(pruned_hi < all_hi);   // the test prunes something
    CHECK(thrown_x < 0.3);       // the thrown block struck the column (free flight: 0.6 m)
    REQUIRE(a.size() == b.size());
    size_t differ = 0;
    for (size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
    // a pruned face carries no force at any step: same sums in the same order, same bits
    CHECK(differ == 0);
}

TEST_CASE("a block turning past the pruning's bound between refreshes gets its faces back, bit-identical", "[dem][contact]") {
    // a cube released on one edge, tilted past its balance: it topples and lands on its side.
    // Refreshed only when a point could cross the 0.2 m margin (the interval never comes due),
    // so it turns by up to ~0.4 rad between refreshes, far past kRefreshTurn: the faces the
    // refresh left out as not facing the base must come back as it turns (without, the run
    // differs from the unpruned one)
    Scene s = test::stone_scene(0.3);
    s.contact.scheme = ContactScheme::overlap;
    s.contact.kn = s.contact.ks = 1e9;
    s.run.contact_interval = 1000000;
    add_box(s, "base", Vec3(2, 2, 0.5), Vec3(0, 0, -0.25), true);
    const double tilt = 0.9;   // rad, about y: the centre of mass is past the edge at x = 0.15
    const Quat q(Eigen::AngleAxisd(tilt, Vec3::UnitY()));
    const Vec3 edge(0.15, 0.0, 0.0);
    // the cube's lowest edge (block frame x = 0.15, z = −0.15) on the base, sunk 0.1 mm
    add_box(s, "cube", Vec3(0.3, 0.3, 0.3), edge - q * Vec3(0.15, 0.0, -0.15) - Vec3(0, 0, 1e-4), false, q);
    double turned = 0.0;   // the cube's final turn about y, rad
    auto run = [&](bool prune, size_t& fewest) {
        dem::World w(s, 0.2);
        w.prune_contacts(prune);
        w.start(2e-5);
        std::vector<Vec3> x;
        fewest = 1u << 30;
        for (int i = 0; i < 40000; ++i) {
            const bool ok = w.step();
            INFO("step " << i << ": " << w.failure());
            REQUIRE(ok);
            fewest = std::min(fewest, w.candidate_count());
            const auto& b = w.blocks().back();
            x.push_back(b.body.x), x.push_back(b.body.L);
        }
        x.push_back(Vec3(w.energy().contact, w.energy().dissipated, w.kinetic()));
        turned = dem::rotation_vector(w.blocks().back().body.q).y();
        return x;
    };
    size_t pruned_fewest = 0, all_fewest = 0;
    const auto b = run(false, all_fewest), a = run(true, pruned_fewest);
    INFO("candidates pruned at fewest " << pruned_fewest << ", all " << all_fewest);
    CHECK(pruned_fewest < all_fewest);   // the test prunes something
    INFO("turned " << turned << " rad about y");
    CHECK(turned > 1.4);   // it toppled onto its +x side (π/2 less the bounce)
    REQUIRE(a.size() == b.size());
    size_t differ = 0;
    for (size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
    CHECK(differ == 0);
}
