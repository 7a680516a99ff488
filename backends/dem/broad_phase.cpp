#include "broad_phase.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numeric>

namespace cairn::dem {

namespace {

constexpr size_t kGridFrom = 64;        // fewer boxes: the sweep is as quick
constexpr double kLarge = 4.0;          // a box larger than this many cells is tested against all
constexpr int32_t kMaxCell = 1 << 20;   // cell indices per axis (20 bits each in a key)

uint64_t cell_key(int32_t i, int32_t j, int32_t k) {
    return (uint64_t(uint32_t(i)) << 42) | (uint64_t(uint32_t(j)) << 21) | uint64_t(uint32_t(k));
}

// a well-mixed bucket index for a key (splitmix64 finaliser)
uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

}  // namespace

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

void BroadPhase::overlapping_pairs(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs) {
    if (boxes.size() < kGridFrom || !grid(boxes, pairs)) {
        cell_ = 0.0;
        dem::overlapping_pairs(boxes, order_, pairs);
    }
}

// false when the boxes do not suit a grid (no finite positive median size, or a span of more
// than kMaxCell cells): the caller sweeps instead
bool BroadPhase::grid(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs) {
    const size_t n = boxes.size();
    extent_.resize(n);
    for (size_t i = 0; i < n; ++i) extent_[i] = (boxes[i].hi - boxes[i].lo).maxCoeff();
    // the cell: the median box size (linear-time selection on a copy)
    median_.assign(extent_.begin(), extent_.end());
    std::nth_element(median_.begin(), median_.begin() + long(n / 2), median_.end());
    const double h = median_[n / 2];
    range_.resize(n);
    if (!(h > 0.0) || !std::isfinite(h)) return false;
    // the origin and span of the boxes that go into the grid
    large_.clear();
    Vec3 origin = Vec3::Constant(1e300), top = Vec3::Constant(-1e300);
    for (size_t i = 0; i < n; ++i) {
        if (!(extent_[i] <= kLarge * h)) {
            large_.push_back(int(i));
            continue;
        }
        origin = origin.cwiseMin(boxes[i].lo);
        top = top.cwiseMax(boxes[i].hi);
    }
    if (((top - origin) / h).maxCoeff() >= double(kMaxCell - 2)) return false;
    cell_ = h;
    // every cell of every grid box, then the entries by hash bucket (counting sort)
    entry_.clear();
    for (size_t i = 0; i < n; ++i) {
        if (!(extent_[i] <= kLarge * h)) continue;
        auto& r = range_[i];
        for (int a = 0; a < 3; ++a) {
            r[size_t(a)] = int32_t(std::floor((boxes[i].lo[a] - origin[a]) / h));
            r[size_t(a) + 3] = int32_t(std::floor((boxes[i].hi[a] - origin[a]) / h));
        }
        for (int32_t k = r[2]; k <= r[5]; ++k)
            for (int32_t j = r[1]; j <= r[4]; ++j)
                for (int32_t c = r[0]; c <= r[3]; ++c) entry_.emplace_back(cell_key(c, j, k), int(i));
    }
    size_t buckets = 1;
    while (buckets < 2 * entry_.size()) buckets *= 2;
    start_.assign(buckets + 1, 0);
    for (const auto& e : entry_) ++start_[(mix(e.first) & (buckets - 1)) + 1];
    for (size_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
    sorted_.resize(entry_.size());
    for (const auto& e : entry_) sorted_[size_t(start_[mix(e.first) & (buckets - 1)]++)] = e;
    // start_[b] is now the end of bucket b; its start is start_[b − 1] (0 for the first)
    pairs.clear();
    for (size_t b = 0; b < buckets; ++b) {
        const int lo = b == 0 ? 0 : start_[b - 1], hi = start_[b];
        for (int x = lo; x < hi; ++x)
            for (int y = x + 1; y < hi; ++y) {
                const auto& [key, i] = sorted_[size_t(x)];
                const int j = sorted_[size_t(y)].second;
                if (sorted_[size_t(y)].first != key || !boxes[size_t(i)].overlaps(boxes[size_t(j)])) continue;
                // both boxes share several cells: the pair is reported by the one holding the
                // lower corner of their intersection (the larger lower cell on each axis)
                const auto& ri = range_[size_t(i)];
                const auto& rj = range_[size_t(j)];
                if (cell_key(std::max(ri[0], rj[0]), std::max(ri[1], rj[1]), std::max(ri[2], rj[2])) != key) continue;
                pairs.emplace_back(std::min(i, j), std::max(i, j));
            }
    }
    // large boxes against every other box (a large pair once)
    for (int l : large_)
        for (size_t j = 0; j < n; ++j) {
            const bool other_large = !(extent_[j] <= kLarge * h);
            if (int(j) == l || (other_large && int(j) < l)) continue;
            if (boxes[size_t(l)].overlaps(boxes[j])) pairs.emplace_back(std::min(l, int(j)), std::max(l, int(j)));
        }
    std::sort(pairs.begin(), pairs.end());
    return true;
}

}  // namespace cairn::dem
