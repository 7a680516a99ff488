#include "geometry/overlap.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace cairn {

namespace {

// the 12 edges of a hexahedron as corner pairs (hex8 order)
constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                               {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// outward normal of face f from its diagonals (robust for slightly warped faces)
Vec3 face_normal(const Corners& c, int f) {
    const auto& fc = kFaceCorners[f];
    return (c[fc[2]] - c[fc[0]]).cross(c[fc[3]] - c[fc[1]]);
}

}  // namespace

double overlap_depth(const Corners& a, const Corners& b) {
    double scale = 0.0;
    for (const auto& p : a) scale = std::max(scale, p.cwiseAbs().maxCoeff());
    for (const auto& p : b) scale = std::max(scale, p.cwiseAbs().maxCoeff());
    double depth = std::numeric_limits<double>::infinity();
    auto axis = [&](Vec3 n) {
        const double len = n.norm();
        // parallel edges give no axis (their cross product vanishes)
        if (!(len > 1e-12 * std::max(1.0, scale * scale))) return;
        n /= len;
        double lo_a = 1e300, hi_a = -1e300, lo_b = 1e300, hi_b = -1e300;
        for (const auto& p : a) lo_a = std::min(lo_a, n.dot(p)), hi_a = std::max(hi_a, n.dot(p));
        for (const auto& p : b) lo_b = std::min(lo_b, n.dot(p)), hi_b = std::max(hi_b, n.dot(p));
        depth = std::min(depth, std::min(hi_a - lo_b, hi_b - lo_a));
    };
    for (int f = 0; f < 6; ++f) axis(face_normal(a, f)), axis(face_normal(b, f));
    for (const auto& ea : kEdges)
        for (const auto& eb : kEdges) axis((a[ea[1]] - a[ea[0]]).cross(b[eb[1]] - b[eb[0]]));
    return depth;
}

Corners placed_corners(const Corners& frame, const Vec3& position, const Quat& orientation) {
    Corners w;
    for (int i = 0; i < 8; ++i) w[i] = position + orientation * frame[i];
    return w;
}

}  // namespace cairn
