// A running-bond wall released touching settles under gravity by the sum of its joints'
// compressions (compare/bench/scale_bench: ρ g h C(C + 1)/(2 kn)), on dem's overlap scheme; and
// the 300-brick wall gives the same bits on 1 and 2 threads.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "bench/scale_bench.hpp"
#include "bench/wall_bench.hpp"
#include "dem/dem_backend.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace cairn;

TEST_CASE("dem settles a 10-course wall by the sum of its joints' compressions", "[dem][physics][scale]") {
    const auto acc = bench::scale_accuracy({"dem"}, {3e-4}, 0.01, [](const std::string&) { return dem_backend_info().make(); },
                                           true);
    REQUIRE(acc.size() == 1);
    CHECK(acc[0].status == "completed");
    // 1 %: the bench's accuracy bar; the flat joints' normal force is exact, what is left is the
    // residual motion under the mass damping after 0.3 s and the running bond's overhanging ends
    CHECK(std::abs(acc[0].error) < 0.01);
    CHECK(acc[0].expected == Approx(bench::wall_settlement(10, 2600, 9.81, 0.2, 3e9)));
}

#ifdef _OPENMP
TEST_CASE("the 300-brick wall gives the same bits on 1 and 2 threads", "[dem][determinism]") {
    // above 256 blocks the rigid stages and the contact run on every core: the thread count must
    // not change a single bit of the state
    for (auto scheme : {ContactScheme::paper, ContactScheme::overlap}) {
        Scene s = bench::wall_scene(30, 10, bench::wall_setups()[1]);
        s.contact.scheme = scheme;
        s.contact.subdivision = 2;
        s.gravity = Vec3(0.3, 0.1, -9.81);   // a little sideways: shear anchors and slip are exercised
        auto run = [&](int threads) {
            omp_set_num_threads(threads);
            auto b = dem_backend_info().make();
            b->build(s, RunOptions{});
            for (int i = 0; i < 60; ++i) REQUIRE(b->step() == StepStatus::ok);
            const Sample x = b->sample();
            std::vector<double> state{x.energy.contact, x.energy.dissipated, double(x.contacts)};
            for (const auto& bl : x.blocks)
                for (double v : {bl.position.x(), bl.position.y(), bl.position.z(), bl.orientation.w(),
                                 bl.orientation.x(), bl.velocity.z()})
                    state.push_back(v);
            return state;
        };
        const auto one = run(1), two = run(2);
        omp_set_num_threads(2);
        CHECK(one[2] > 300);
        CHECK(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)) == 0);
    }
}
#endif
