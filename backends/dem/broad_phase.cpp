#include "broad_phase.hpp"

#include <algorithm>
#include <cassert>
#include <numeric>

namespace cairn::dem {

void overlapping_pairs(const std::vector<Aabb>& boxes, std::vector<int>& order,
                       std::vector<std::pair<int, int>>& pairs) {
    order.resize(boxes.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return boxes[a].lo.x() < boxes[b].lo.x() || (boxes[a].lo.x() == boxes[b].lo.x() && a < b);
    });
    pairs.clear();
    for (size_t a = 0; a < order.size(); ++a) {
        const Aabb& ba = boxes[order[a]];
        assert((ba.lo.array() <= ba.hi.array()).all() && "a box's low corner is below its high corner");
        for (size_t b = a + 1; b < order.size(); ++b) {
            const Aabb& bb = boxes[order[b]];
            if (bb.lo.x() > ba.hi.x()) break;
            if (ba.overlaps(bb)) pairs.emplace_back(std::min(order[a], order[b]), std::max(order[a], order[b]));
        }
    }
    std::sort(pairs.begin(), pairs.end());
}

}  // namespace cairn::dem
