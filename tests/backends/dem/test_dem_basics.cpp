// The rigid-block engine against closed forms: free fall, a block resting on a penalty spring,
// energy closure and determinism.
#include <catch2/catch.hpp>

#include <algorithm>

#include <cmath>
#include <string>
#include <vector>

#include "analytic/oracles.hpp"
#include "dem_test_util.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

TEST_CASE("free fall is exact to rounding: leapfrog integrates constant acceleration exactly", "[dem]") {
    Scene s = test::stone_scene();
    s.run.dt = 1e-3;
    test::add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 10), false);
    s.blocks[0].velocity = Vec3(1.0, 0.0, 2.0);
    auto b = test::build_dem(s);
    Sample last;
    test::run_dem(*b, 0.5, [&](const Sample& x) { last = x; });
    const double t = last.t;
    // rounding over 500 steps of O(1) numbers: 1e-9 m is many orders above it and far below any
    // integrator error (a first-order scheme would be off by g·dt·t/2 = 2.5e-3 m)
    CHECK(last.blocks[0].position.x() == Approx(1.0 * t).margin(1e-9));
    CHECK(last.blocks[0].position.z() == Approx(10 + 2.0 * t - 0.5 * 9.81 * t * t).margin(1e-9));
    CHECK(last.blocks[0].velocity.z() == Approx(2.0 - 9.81 * t).margin(1e-9));
    CHECK(last.contacts == 0);
}

TEST_CASE("paper case (a): a cube resting on a fixed cube reaches mg/(kn·A) and period 2π√(m/(kn·A))",
          "[dem][paper]") {
    Scene s = test::stone_scene();
    test::add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    test::add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);
    auto b = test::build_dem(s);
    oracle::RestingBlock ref{2600.0, 3e7 * 1.0, 9.81};
    REQUIRE(ref.penetration() == Approx(8.502e-4).epsilon(1e-3));
    REQUIRE(ref.period() == Approx(0.058493).epsilon(1e-4));
    std::vector<double> t, z;
    test::run_dem(*b, 0.5, [&](const Sample& x) {
        t.push_back(x.t);
        z.push_back(x.blocks[0].position.z() - 0.5);
    });
    // penetration swings between 0 and 2d around the equilibrium d
    double zmin = *std::min_element(z.begin(), z.end());
    double zmax = *std::max_element(z.begin(), z.end());
    // 1 %: the tolerance; the discrete step (dt = 0.1 dt_crit) and the sampled extrema
    // are both well inside it (period error (ω dt)²/24 < 1e-3)
    CHECK(-0.5 * (zmin + zmax) == Approx(ref.penetration()).epsilon(0.01));
    CHECK(-zmin == Approx(2 * ref.penetration()).epsilon(0.01));
    // period from upward crossings of the equilibrium, linearly interpolated
    std::vector<double> up;
    const double zeq = -ref.penetration();
    for (size_t i = 1; i < z.size(); ++i)
        if (z[i - 1] < zeq && z[i] >= zeq) up.push_back(t[i - 1] + (zeq - z[i - 1]) / (z[i] - z[i - 1]) * (t[i] - t[i - 1]));
    REQUIRE(up.size() >= 5);
    double period = (up.back() - up.front()) / double(up.size() - 1);
    CHECK(period == Approx(ref.period()).epsilon(0.01));
}

TEST_CASE("energy balance closes for an undamped oscillation and a damped one", "[dem][energy]") {
    for (auto rule : {ContactDampingRule::none, ContactDampingRule::ratio}) {
        Scene s = test::stone_scene();
        s.contact.damping_rule = rule;
        s.contact.damping = rule == ContactDampingRule::ratio ? 0.1 : 0.0;
        test::add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5 + 0.01), false);
        test::add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);
        auto b = test::build_dem(s);
        double e0 = b->sample().energy.total(), worst = 0.0, diss = 0.0;
        test::run_dem(*b, 0.5, [&](const Sample& x) {
            worst = std::max(worst, std::abs(x.energy.total() - e0));
            diss = x.energy.dissipated;
        });
        // scale: the energy that moves through the contact, m g (gap + 2d) ≈ 2600·9.81·0.0127 J.
        // undamped: the leapfrog shadow energy differs from the true one by O((ω dt)²) ≈ 1e-2
        // of the contact energy (measured 0.1 % of the scale). damped: the dashpot's work is
        // booked with the half-step velocity, first order: error ≈ ζ·ω·dt ≈ 1 % of what it
        // dissipates (measured 1.2 % of the scale)
        const double scale = 2600 * 9.81 * 0.0127;
        CHECK(worst < (rule == ContactDampingRule::none ? 0.005 : 0.02) * scale);
        if (rule == ContactDampingRule::ratio) CHECK(diss > 0.5 * scale);
        // undamped: nothing dissipates but the shear springs given up when the block leaves the
        // contact (booked as dissipated): their offsets are rounding, 1e-12 of the scale at most
        else { INFO("dissipated " << diss << " J"); CHECK(std::abs(diss) < 1e-12 * scale); }
    }
}

TEST_CASE("the same scene twice gives identical samples", "[dem][determinism]") {
    Scene s = test::stone_scene(0.4);
    test::add_box(s, "A", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 0.25), false);
    test::add_box(s, "B", Vec3(4.0, 0.7, 1.0), Vec3(0, 0, -0.5), true);
    LoadDef push;
    push.force = Vec3(1594.125, 0, 300);
    push.point = Vec3(0.1, 0.2, 0.25);
    s.loads.push_back(push);
    auto run = [&] {
        auto b = test::build_dem(s);
        std::vector<double> out;
        test::run_dem(*b, 0.2, [&](const Sample& x) {
            for (int k = 0; k < 3; ++k) out.push_back(x.blocks[0].position[k]);
            for (int k = 0; k < 4; ++k) out.push_back(x.blocks[0].orientation.coeffs()[k]);
            out.push_back(x.energy.total());
        });
        return out;
    };
    CHECK(run() == run());
}

TEST_CASE("a scene's block order and names do not change its results, to the last bit", "[dem][determinism]") {
    // a column of three 0.4 x 0.4 x 0.5 m drums rocked by a push at its top; the same blocks listed
    // in the other order under other names (a scene holds its blocks in name order). The engine
    // sums forces block by block: held in the scene's order, the two runs parted at rounding and
    // the rocking impacts grew it to 4 mm by 3 s on a shaken column (session 19)
    auto column = [](const std::vector<std::string>& names) {
        Scene s = test::stone_scene(0.7);
        s.contact.kn = s.contact.ks = 1e9;
        test::add_box(s, "base", Vec3(2.0, 2.0, 0.5), Vec3(0, 0, -0.25), true);
        for (int k = 0; k < 3; ++k) test::add_box(s, names[size_t(k)], Vec3(0.4, 0.4, 0.5), Vec3(0, 0, 0.25 + 0.5 * k), false);
        std::sort(s.blocks.begin(), s.blocks.end(), [](const BlockDef& a, const BlockDef& b) { return a.name < b.name; });
        LoadDef push;
        push.block = s.block_index(names[2]);
        push.force = Vec3(1200, 300, 0);
        push.point = Vec3(0, 0, 0.25);
        push.ramp = 0.05;
        s.loads.push_back(push);
        return s;
    };
    auto run = [](const Scene& s, const std::vector<std::string>& order) {
        auto b = test::build_dem(s);
        std::vector<double> out;
        test::run_dem(*b, 0.6, [&](const Sample& x) {
            for (const auto& name : order) {
                int f = 0;   // free-block index of `name` in the scene's order
                for (const auto& d : s.blocks) {
                    if (d.name == name) break;
                    if (!d.fixed) ++f;
                }
                const auto& st = x.blocks.at(size_t(f));
                for (int k = 0; k < 3; ++k) out.push_back(st.position[k]);
                for (int k = 0; k < 4; ++k) out.push_back(st.orientation.coeffs()[k]);
            }
            out.push_back(x.energy.total());
        });
        return out;
    };
    const std::vector<std::string> a{"d1", "d2", "d3"}, b{"z", "m", "a"};   // bottom to top
    const Scene first = column(a), second = column(b);
    REQUIRE(first.blocks[0].name == "base");   // listed base, bottom, middle, top
    REQUIRE(second.blocks[0].name == "a");     // listed top, base, middle, bottom
    const auto x = run(first, a), y = run(second, b);
    REQUIRE(x.size() == y.size());
    CHECK(x == y);
}

TEST_CASE("a contact too soft for its load stops the run instead of letting a block sink through", "[dem][stability]") {
    // kn = 1e5 N/m³ under a 1 m cube: the static penetration m g/(kn A) = 0.26 m is more than a
    // quarter of the block; the engine must say so, not hand back a block falling through its base
    Scene s = test::stone_scene();
    s.contact.kn = s.contact.ks = 1e5;
    test::add_box(s, "A", Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    test::add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);
    auto b = test::build_dem(s);
    bool stopped = !test::run_dem(*b, 2.0, [](const Sample&) {});
    REQUIRE(stopped);
    CHECK_THAT(b->failure(), Catch::Contains("block A sank") && Catch::Contains("into block B"));
    // it stopped as the penetration passed 0.25 m, not after the block fell through
    CHECK(b->sample().blocks[0].position.z() > 0.5 - 0.3);
}

#ifdef _OPENMP
#include <omp.h>
TEST_CASE("a meshed block in contact gives the same bits on 1 and 2 threads", "[dem][determinism]") {
    // elements and contact candidates are shared between the cores, their forces gathered in a
    // fixed order: the thread count must not change a single bit
    Scene s = test::stone_scene(0.6);
    test::add_box(s, "A", Vec3(1, 1, 1), Vec3(0.05, 0, 0.5), false);
    test::add_box(s, "B", Vec3(1, 1, 1), Vec3(0, 0, -0.5), true);
    s.blocks[0].model = BlockModel::deformable;
    s.blocks[0].mesh.divisions = {6, 6, 6};
    s.blocks[0].angular_velocity = Vec3(0.2, 0.1, 0.0);
    auto run = [&](int threads) {
        omp_set_num_threads(threads);
        auto b = test::build_dem(s);
        for (int i = 0; i < 300; ++i) b->step();
        Sample x = b->sample();
        return std::vector<double>{x.blocks[0].position.x(), x.blocks[0].position.z(), x.blocks[0].orientation.w(),
                                   x.energy.contact, x.energy.strain, x.energy.dissipated, double(x.contacts)};
    };
    const auto one = run(1), two = run(2);
    CHECK(one == two);
    // the overlap scheme, 8 x 8 sub-contacts per element face: past the parallel threshold too
    s.contact.scheme = ContactScheme::overlap;
    s.contact.subdivision = 8;
    const auto one_o = run(1), two_o = run(2);
    omp_set_num_threads(2);
    CHECK(one_o[6] > 100);
    CHECK(one_o == two_o);
}
#endif

TEST_CASE("run notes name each model once, with the blocks that have it", "[dem]") {
    // a generated wall of 10⁴ bricks wrote one note per brick into run.json; now one per model
    Scene s = test::stone_scene();
    for (int i = 0; i < 8; ++i) test::add_box(s, "b" + std::to_string(i), Vec3(0.4, 0.2, 0.2), Vec3(0.5 * i, 0, 0.1), false);
    test::add_box(s, "C", Vec3(0.4, 0.4, 0.4), Vec3(0, 2, 0.2), false);
    s.blocks.back().model = BlockModel::deformable;
    test::add_box(s, "base", Vec3(6, 4, 0.5), Vec3(2, 1, -0.25), true);
    auto b = test::build_dem(s);
    std::vector<std::string> models;
    for (const auto& n : b->notes())
        if (n.find(": rigid") != std::string::npos || n.find(": deformable") != std::string::npos) models.push_back(n);
    REQUIRE(models.size() == 2);
    CHECK(models[0] == "8 blocks (b0, b1, b2, b3, b4, … b7): rigid");
    CHECK(models[1].rfind("block C: deformable, 1x1x1 hex8", 0) == 0);
}
