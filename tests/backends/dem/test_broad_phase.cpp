// Broad phase: sweep and prune gives exactly the overlapping pairs of a brute-force check.
#include <catch2/catch.hpp>

#include <random>

#include "dem/broad_phase.hpp"

using namespace cairn;

TEST_CASE("sweep and prune finds exactly the overlapping pairs of random boxes", "[dem][contact]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> pos(0.0, 10.0), size(0.05, 1.5);
    for (int trial = 0; trial < 5; ++trial) {
        std::vector<Aabb> boxes(200);
        for (auto& b : boxes) {
            const Vec3 lo(pos(rng), pos(rng), pos(rng));
            b.add(lo);
            b.add(lo + Vec3(size(rng), size(rng), size(rng)));
        }
        // a few boxes sharing a lower x edge exactly (ties of the sort)
        boxes[1].lo.x() = boxes[0].lo.x();
        std::vector<int> order;
        std::vector<std::pair<int, int>> pairs, brute;
        dem::overlapping_pairs(boxes, order, pairs);
        for (int i = 0; i < int(boxes.size()); ++i)
            for (int j = i + 1; j < int(boxes.size()); ++j)
                if (boxes[i].overlaps(boxes[j])) brute.emplace_back(i, j);
        CHECK(pairs == brute);
        CHECK(!brute.empty());
    }
}
