#include "siconos_contacts.hpp"

#include <algorithm>
#include <numeric>

#include <Eigen/LU>

#include "hexahedron_contact.hpp"

namespace cairn {

Corners inflated_corners(const Corners& c, double margin) {
    Vec3 centre = Vec3::Zero();
    for (const Vec3& p : c) centre += p / 8.0;
    // each face plane n·x = n·(face centre) + margin, with the mean normal of a warped face
    std::array<Vec3, 6> normal;
    std::array<double, 6> offset;
    for (int f = 0; f < 6; ++f) {
        const auto& k = kFaceCorners[f];
        Vec3 n = (c[k[2]] - c[k[0]]).cross(c[k[3]] - c[k[1]]).normalized();
        Vec3 face_centre = (c[k[0]] + c[k[1]] + c[k[2]] + c[k[3]]) / 4.0;
        if (n.dot(face_centre - centre) < 0) n = -n;
        normal[f] = n;
        offset[f] = n.dot(face_centre) + margin;
    }
    // each corner: where its three face planes meet
    Corners out;
    for (int i = 0; i < 8; ++i) {
        Mat3 m;
        Vec3 rhs;
        int row = 0;
        for (int f = 0; f < 6 && row < 3; ++f)
            if (std::find(kFaceCorners[f].begin(), kFaceCorners[f].end(), i) != kFaceCorners[f].end()) {
                m.row(row) = normal[f].transpose();
                rhs[row] = offset[f];
                ++row;
            }
        out[i] = m.partialPivLu().solve(rhs);
    }
    return out;
}

std::vector<GapContact> gap_contacts(const Corners& a, const Corners& b, double margin, int max_points) {
    std::vector<GapContact> out;
    const auto near = hexahedron_contacts(inflated_corners(a, 0.5 * margin), inflated_corners(b, 0.5 * margin), 1);
    if (near.empty()) return out;
    const Vec3 n = near.front().normal;
    Corners shifted = a;
    for (Vec3& p : shifted) p -= margin * n;
    for (const HexContact& h : hexahedron_contacts(shifted, b, max_points)) {
        // shifted a's surface lies d/2 below the midpoint, b's d/2 above; a itself is `margin`
        // back along n (projected on this pair's normal, which the shift may have changed)
        GapContact c;
        c.normal = h.normal;
        const double back = margin * n.dot(h.normal);
        c.on_a = h.position + (back - 0.5 * h.depth) * h.normal;
        c.on_b = h.position + 0.5 * h.depth * h.normal;
        c.gap = back - h.depth;
        out.push_back(c);
    }
    return out;
}

std::vector<std::pair<int, int>> near_pairs(const std::vector<Corners>& corners, const std::vector<bool>& fixed,
                                            double margin) {
    const int n = static_cast<int>(corners.size());
    std::vector<Vec3> lo(n), hi(n);
    for (int i = 0; i < n; ++i) {
        lo[i] = hi[i] = corners[i][0];
        for (const Vec3& p : corners[i]) {
            lo[i] = lo[i].cwiseMin(p);
            hi[i] = hi[i].cwiseMax(p);
        }
        lo[i].array() -= margin;
        hi[i].array() += margin;
    }
    // sweep along x: blocks sorted by their lowest x (ties by index, so the order is fixed)
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int i, int j) { return lo[i].x() < lo[j].x() || (lo[i].x() == lo[j].x() && i < j); });
    std::vector<std::pair<int, int>> pairs;
    for (int s = 0; s < n; ++s) {
        const int i = order[s];
        for (int t = s + 1; t < n && lo[order[t]].x() <= hi[i].x(); ++t) {
            const int j = order[t];
            if (fixed[i] && fixed[j]) continue;
            if ((lo[i].array() > hi[j].array()).any() || (lo[j].array() > hi[i].array()).any()) continue;
            pairs.emplace_back(std::min(i, j), std::max(i, j));
        }
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

}  // namespace cairn
