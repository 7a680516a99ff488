// blocks that overlap at t = 0: refused, with the pair and the depth
#include <algorithm>
#include <cstdio>
#include <numeric>

#include "error.hpp"
#include "geometry/overlap.hpp"
#include "scene/scene_read.hpp"

namespace cairn::scene_detail {

namespace {

std::string number(double x) { return message_number(x, 3); }

}  // namespace

void check_overlaps(const TableReader& root, const Scene& scene) {
    const size_t n = scene.blocks.size();
    std::vector<Corners> world(n);
    std::vector<Aabb> box(n);
    for (size_t i = 0; i < n; ++i) {
        const BlockDef& b = scene.blocks[i];
        world[i] = placed_corners(b.corners, b.position, b.orientation);
        for (const auto& p : world[i]) box[i].add(p);
    }
    // sweep along x: only pairs whose bounding boxes meet are tested exactly
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return box[a].lo.x() < box[b].lo.x(); });
    TableReader blocks(root.sources(), root.require("blocks").table(), "blocks");
    for (size_t oi = 0; oi < n; ++oi) {
        const size_t i = order[oi];
        for (size_t oj = oi + 1; oj < n && box[order[oj]].lo.x() <= box[i].hi.x(); ++oj) {
            const size_t j = order[oj];
            const BlockDef &a = scene.blocks[i], &b = scene.blocks[j];
            if (a.fixed && b.fixed) continue;   // fixed blocks never touch each other in any engine
            if (!box[i].overlaps(box[j])) continue;
            const double edge = std::min(shortest_edge(a.corners), shortest_edge(b.corners));
            const double depth = overlap_depth(world[i], world[j]);
            if (depth <= kOverlapTolerance * edge) continue;
            // name the position of the free block (the later one in name order if both are free)
            const BlockDef& named = a.fixed ? b : (b.fixed ? a : (i < j ? b : a));
            const BlockDef& other = &named == &a ? b : a;
            const Item table = blocks.get(named.name);
            const Item pos = TableReader(root.sources(), table.table(), table.key()).get("position");
            const Item& where = pos ? pos : table;
            where.fail("block " + named.name + " overlaps block " + other.name + " by " + number(depth) +
                       " m at t = 0, more than " + number(kOverlapTolerance * 100) +
                       " % of the smaller block's shortest edge (" + number(edge) +
                       " m); move the blocks apart");
        }
    }
}

}  // namespace cairn::scene_detail
