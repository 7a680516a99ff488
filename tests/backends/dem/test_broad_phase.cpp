// Broad phase: sweep and prune, and the hashed grid, give exactly the overlapping pairs of a
// brute-force check.
#include <catch2/catch.hpp>

#include <random>

#include "dem/broad_phase.hpp"

using namespace cairn;

namespace {

std::vector<std::pair<int, int>> brute_force(const std::vector<Aabb>& boxes) {
    std::vector<std::pair<int, int>> out;
    for (int i = 0; i < int(boxes.size()); ++i)
        for (int j = i + 1; j < int(boxes.size()); ++j)
            if (boxes[i].overlaps(boxes[j])) out.emplace_back(i, j);
    return out;
}

std::vector<Aabb> random_boxes(std::mt19937& rng, int count, double span, double smallest, double largest) {
    std::uniform_real_distribution<double> pos(0.0, span), size(smallest, largest);
    std::vector<Aabb> boxes(static_cast<size_t>(count), Aabb{});
    for (auto& b : boxes) {
        const Vec3 lo(pos(rng), pos(rng), pos(rng));
        b.add(lo);
        b.add(lo + Vec3(size(rng), size(rng), size(rng)));
    }
    return boxes;
}

}  // namespace

TEST_CASE("sweep and prune finds exactly the overlapping pairs of random boxes", "[dem][contact]") {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 5; ++trial) {
        auto boxes = random_boxes(rng, 200, 10.0, 0.05, 1.5);
        // two boxes sharing a lower x edge exactly (ties of the sort): box 1 moved along x whole,
        // keeping its width (a box whose low corner passed its high one is refused by an assertion)
        const double width = boxes[1].hi.x() - boxes[1].lo.x();
        boxes[1].lo.x() = boxes[0].lo.x();
        boxes[1].hi.x() = boxes[0].lo.x() + width;
        std::vector<int> order;
        std::vector<std::pair<int, int>> pairs;
        dem::overlapping_pairs(boxes, order, pairs);
        const auto brute = brute_force(boxes);
        CHECK(pairs == brute);
        CHECK(!brute.empty());
    }
}

TEST_CASE("the hashed grid finds exactly the overlapping pairs of random boxes", "[dem][contact]") {
    std::mt19937 rng(5);
    dem::BroadPhase bp;   // one object over every trial: its kept scratch must not leak between calls
    for (int trial = 0; trial < 6; ++trial) {
        // sizes over two decades, some boxes many cells large (tested against all)
        auto boxes = random_boxes(rng, 1500, 12.0, 0.02, trial % 2 ? 0.6 : 2.5);
        boxes[3].lo = Vec3(-1, -1, -1), boxes[3].hi = Vec3(13, 13, 0.2);   // a ground under all
        boxes[7].lo = Vec3(5, 5, 5), boxes[7].hi = Vec3(9, 9, 9);
        std::vector<std::pair<int, int>> pairs;
        bp.overlapping_pairs(boxes, pairs);
        CHECK(bp.cell() > 0.0);
        const auto brute = brute_force(boxes);
        CHECK(pairs.size() == brute.size());
        CHECK(pairs == brute);
    }
}

TEST_CASE("the hashed grid finds the touching bricks of a running-bond wall", "[dem][contact]") {
    // bricks placed exactly face to face: every touching pair (closed boxes) is found, along with
    // the ground under them all
    std::vector<Aabb> boxes(1);
    boxes[0].lo = Vec3(-10, -1, -1), boxes[0].hi = Vec3(10, 1, 0);
    for (int c = 0; c < 20; ++c)
        for (int i = 0; i < 12; ++i) {
            Aabb b;
            const double x = -2.4 + 0.4 * i + (c % 2 ? 0.2 : 0.0);
            b.lo = Vec3(x, -0.1, 0.2 * c), b.hi = Vec3(x + 0.4, 0.1, 0.2 * c + 0.2);
            boxes.push_back(b);
        }
    dem::BroadPhase bp;
    std::vector<std::pair<int, int>> pairs;
    bp.overlapping_pairs(boxes, pairs);
    CHECK(bp.cell() > 0.0);
    CHECK(pairs == brute_force(boxes));
}

TEST_CASE("the broad phase sweeps boxes that do not suit a grid", "[dem][contact]") {
    // two clusters 1e9 cells apart: the grid would need more than 2^20 cells per axis
    std::mt19937 rng(3);
    auto boxes = random_boxes(rng, 100, 2.0, 0.1, 0.3);
    for (int i = 0; i < 50; ++i) boxes[size_t(i)].lo.x() += 1e8, boxes[size_t(i)].hi.x() += 1e8;
    dem::BroadPhase bp;
    std::vector<std::pair<int, int>> pairs;
    bp.overlapping_pairs(boxes, pairs);
    CHECK(bp.cell() == 0.0);
    CHECK(pairs == brute_force(boxes));
}
