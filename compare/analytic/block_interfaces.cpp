#include "block_interfaces.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cairn::oracle {

namespace {

/// a face of a block: its corners, outward unit normal, centre (m) and area (m²)
struct Face {
    std::array<Vec3, 4> corners;
    Vec3 normal = Vec3::Zero();
    Vec3 centre = Vec3::Zero();
    double area = 0.0;
};

/// the 6 faces of a hexahedron, normals turned outward from its centroid
std::array<Face, 6> faces_of(const Corners& c) {
    Vec3 centroid = Vec3::Zero();
    for (const Vec3& p : c) centroid += p / 8.0;
    std::array<Face, 6> out;
    for (int f = 0; f < 6; ++f) {
        Face& face = out[f];
        for (int k = 0; k < 4; ++k) face.corners[k] = c[kFaceCorners[f][k]];
        face.centre = 0.25 * (face.corners[0] + face.corners[1] + face.corners[2] + face.corners[3]);
        // the cross product of the diagonals: twice the area of a planar quad, along its normal
        const Vec3 n = (face.corners[2] - face.corners[0]).cross(face.corners[3] - face.corners[1]);
        face.area = 0.5 * n.norm();
        face.normal = n.normalized();
        if (face.normal.dot(face.centre - centroid) < 0) face.normal = -face.normal;
    }
    return out;
}

/// twice the signed area of a 2-D polygon (> 0 counter-clockwise)
double signed_area2(const std::vector<Vec2>& p) {
    double a = 0.0;
    for (size_t i = 0; i < p.size(); ++i) {
        const Vec2& q = p[i];
        const Vec2& r = p[(i + 1) % p.size()];
        a += q.x() * r.y() - q.y() * r.x();
    }
    return a;
}

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// the convex polygon `subject` clipped by the convex counter-clockwise polygon `clip`
std::vector<Vec2> clip_polygon(std::vector<Vec2> subject, const std::vector<Vec2>& clip) {
    for (size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
        const Vec2 a = clip[e], edge = clip[(e + 1) % clip.size()] - a;
        std::vector<Vec2> kept;
        for (size_t i = 0; i < subject.size(); ++i) {
            const Vec2& p = subject[i];
            const Vec2& q = subject[(i + 1) % subject.size()];
            const double sp = cross2(edge, p - a), sq = cross2(edge, q - a);
            if (sp >= 0) kept.push_back(p);
            if ((sp >= 0) != (sq >= 0)) kept.push_back(p + (q - p) * (sp / (sp - sq)));
        }
        subject = std::move(kept);
    }
    return subject;
}

/// drop vertices that repeat their neighbour or lie on the line of their two neighbours (both
/// within `eps`, m)
std::vector<Vec2> tidy_polygon(std::vector<Vec2> p, double eps) {
    bool changed = true;
    while (changed && p.size() >= 3) {
        changed = false;
        for (size_t i = 0; i < p.size(); ++i) {
            const Vec2& prev = p[(i + p.size() - 1) % p.size()];
            const Vec2& next = p[(i + 1) % p.size()];
            const double chord = (next - prev).norm();
            if ((p[i] - prev).norm() < eps || std::abs(cross2(next - prev, p[i] - prev)) < eps * chord) {
                p.erase(p.begin() + long(i));
                changed = true;
                break;
            }
        }
    }
    return p;
}

/// the contact of face a of `first` with face b of `second`, if they touch with positive area
bool face_contact(const Face& a, const Face& b, double gap, BlockInterface& out) {
    // anti-parallel within 1e-6 rad: 1 + cos ≤ 1e-12 / 2
    if (a.normal.dot(b.normal) > -1.0 + 0.5e-12) return false;
    for (const Vec3& q : b.corners)
        if (std::abs(a.normal.dot(q - a.centre)) > gap) return false;
    for (const Vec3& q : a.corners)
        if (std::abs(b.normal.dot(q - b.centre)) > gap) return false;
    // coordinates in the mid-plane, axes from face a
    const Vec3 n = (a.normal - b.normal).normalized();
    const Vec3 origin = a.centre + 0.5 * n.dot(b.centre - a.centre) * n;
    const Vec3 e1 = (a.corners[1] - a.corners[0] - n.dot(a.corners[1] - a.corners[0]) * n).normalized();
    const Vec3 e2 = n.cross(e1);
    auto plane = [&](const std::array<Vec3, 4>& c) {
        std::vector<Vec2> p;
        for (const Vec3& q : c) p.emplace_back(e1.dot(q - origin), e2.dot(q - origin));
        if (signed_area2(p) < 0) std::reverse(p.begin(), p.end());
        return p;
    };
    const double smaller = std::min(a.area, b.area);
    std::vector<Vec2> poly = tidy_polygon(clip_polygon(plane(b.corners), plane(a.corners)), 1e-9 * std::sqrt(smaller));
    if (poly.size() < 3) return false;
    const double area = 0.5 * signed_area2(poly);
    if (area < 1e-9 * smaller) return false;
    out.normal = -n;   // from second into first
    out.area = area;
    out.polygon.clear();
    for (const Vec2& p : poly) out.polygon.push_back(origin + p.x() * e1 + p.y() * e2);
    return true;
}

}  // namespace

std::vector<BlockInterface> find_interfaces(const std::vector<Corners>& corners, const std::vector<bool>& fixed,
                                            double gap) {
    const int n = int(corners.size());
    std::vector<Aabb> boxes(n);
    std::vector<std::array<Face, 6>> faces(n);
    for (int i = 0; i < n; ++i) {
        for (const Vec3& p : corners[i]) boxes[i].add(p);
        boxes[i].inflate(gap);
        faces[i] = faces_of(corners[i]);
    }
    std::vector<BlockInterface> out;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            if ((fixed[i] && fixed[j]) || !boxes[i].overlaps(boxes[j])) continue;
            for (const Face& a : faces[i])
                for (const Face& b : faces[j]) {
                    BlockInterface c;
                    if (!face_contact(a, b, gap, c)) continue;
                    c.first = i;
                    c.second = j;
                    out.push_back(std::move(c));
                }
        }
    return out;
}

std::vector<Vec3> inset_polygon(const std::vector<Vec3>& polygon, const Vec3& normal, double inset) {
    if (inset <= 0.0 || polygon.size() < 3) return polygon;
    // 2-D coordinates in the polygon's plane, counter-clockwise about `normal`
    const Vec3 o = polygon[0], u = (polygon[1] - o).normalized(), v = normal.cross(u);
    std::vector<Vec2> p;
    for (const Vec3& x : polygon) p.emplace_back((x - o).dot(u), (x - o).dot(v));
    if (signed_area2(p) < 0) std::reverse(p.begin(), p.end());
    Vec2 centre = Vec2::Zero();
    for (const Vec2& x : p) centre += x / double(p.size());
    std::vector<Vec2> q = p;
    for (size_t e = 0; e < p.size() && !q.empty(); ++e) {   // keep the side of each edge moved `inset` inward
        const Vec2 a = p[e], edge = p[(e + 1) % p.size()] - a;
        const double len = edge.norm();
        std::vector<Vec2> kept;
        for (size_t i = 0; i < q.size(); ++i) {
            const Vec2& x = q[i];
            const Vec2& y = q[(i + 1) % q.size()];
            const double sx = cross2(edge, x - a) / len - inset, sy = cross2(edge, y - a) / len - inset;
            if (sx >= 0) kept.push_back(x);
            if ((sx >= 0) != (sy >= 0)) kept.push_back(x + (y - x) * (sx / (sx - sy)));
        }
        q = std::move(kept);
    }
    if (q.empty()) q = {centre};   // narrower than twice the inset: its force at its middle
    std::vector<Vec3> out;
    for (const Vec2& x : q) out.push_back(o + x.x() * u + x.y() * v);
    return out;
}

}  // namespace cairn::oracle
