#include "hexahedron_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace cairn {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// the 12 edges as corner pairs (bottom ring, top ring, verticals)
constexpr std::array<std::array<int, 2>, 12> kEdges = {{
    {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7},
}};

struct Face {
    Vec3 normal = Vec3::Zero();   // unit, outward
    Vec3 centre = Vec3::Zero();   // centroid of the 4 corners
    std::array<Vec3, 4> corners;  // in order around the face
};

struct Solid {
    const Corners* corners = nullptr;
    Vec3 centre = Vec3::Zero();
    std::array<Face, 6> faces;
};

Solid solid(const Corners& c) {
    Solid s;
    s.corners = &c;
    for (const Vec3& p : c) s.centre += p / 8.0;
    for (int f = 0; f < 6; ++f) {
        Face& face = s.faces[f];
        for (int k = 0; k < 4; ++k) {
            face.corners[k] = c[kFaceCorners[f][k]];
            face.centre += face.corners[k] / 4.0;
        }
        // the diagonals' cross product: the mean normal of a slightly warped face
        face.normal = (face.corners[2] - face.corners[0]).cross(face.corners[3] - face.corners[1]).normalized();
        if (face.normal.dot(face.centre - s.centre) < 0) face.normal = -face.normal;
    }
    return s;
}

void project(const Corners& c, const Vec3& axis, double& lo, double& hi) {
    lo = kInf;
    hi = -kInf;
    for (const Vec3& p : c) {
        double x = axis.dot(p);
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    }
}

// closest points of segments p0-p1 and q0-q1
void closest_points(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, Vec3& a, Vec3& b) {
    Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    double aa = d1.dot(d1), ee = d2.dot(d2), f = d2.dot(r), c = d1.dot(r), bb = d1.dot(d2);
    double denom = aa * ee - bb * bb;
    double s = denom > 1e-30 ? std::clamp((bb * f - c * ee) / denom, 0.0, 1.0) : 0.0;
    double t = (bb * s + f) / ee;
    if (t < 0) {
        t = 0;
        s = std::clamp(-c / aa, 0.0, 1.0);
    } else if (t > 1) {
        t = 1;
        s = std::clamp((bb - c) / aa, 0.0, 1.0);
    }
    a = p0 + s * d1;
    b = q0 + t * d2;
}

// keep the points of `poly` on the inner side of the plane s·(x - p) <= 0
std::vector<Vec3> clip(const std::vector<Vec3>& poly, const Vec3& s, const Vec3& p) {
    std::vector<Vec3> out;
    const size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3& a = poly[i];
        const Vec3& b = poly[(i + 1) % n];
        double da = s.dot(a - p), db = s.dot(b - p);
        if (da <= 0) out.push_back(a);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// the `count` points of a convex polygon (in order) that span the largest quadrilateral
std::vector<HexContact> largest_subset(const std::vector<HexContact>& c, int count) {
    const int n = static_cast<int>(c.size());
    if (n <= count) return c;
    if (count < 4) {   // fewer than 4 wanted: the deepest ones
        std::vector<HexContact> out = c;
        std::sort(out.begin(), out.end(), [](const HexContact& x, const HexContact& y) { return x.depth > y.depth; });
        out.resize(count);
        return out;
    }
    double best = -1.0;
    std::array<int, 4> pick{0, 1, 2, 3};
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            for (int k = j + 1; k < n; ++k)
                for (int l = k + 1; l < n; ++l) {
                    double area = (c[k].position - c[i].position).cross(c[l].position - c[j].position).norm();
                    if (area > best) {
                        best = area;
                        pick = {i, j, k, l};
                    }
                }
    return {c[pick[0]], c[pick[1]], c[pick[2]], c[pick[3]]};
}

}  // namespace

std::vector<HexContact> hexahedron_contacts(const Corners& ca, const Corners& cb, int max_points) {
    const Solid a = solid(ca), b = solid(cb);
    const double size = std::max((ca[6] - ca[0]).norm(), (cb[6] - cb[0]).norm());

    // face axes: overlap of the other solid below each face plane
    double face_depth = kInf;
    bool reference_on_a = true;
    int reference = -1;
    for (int side = 0; side < 2; ++side) {
        const Solid& x = side == 0 ? a : b;
        const Solid& y = side == 0 ? b : a;
        for (int f = 0; f < 6; ++f) {
            const Face& face = x.faces[f];
            double lo_x, hi_x, lo_y, hi_y;
            project(*x.corners, face.normal, lo_x, hi_x);
            project(*y.corners, face.normal, lo_y, hi_y);
            double depth = hi_x - lo_y;
            if (depth < 0 || hi_y - lo_x < 0) return {};   // a separating plane
            if (depth < face_depth) {
                face_depth = depth;
                reference_on_a = side == 0;
                reference = f;
            }
        }
    }

    // edge-edge axes. Parallel edges share an axis and its depth (a box has four edges along each
    // direction): of the pairs within round-off of the least depth, the one whose segments press
    // deepest into each other along the axis is the pair that touches (the first found could be a
    // far edge, and the contact point between far edges puts the force at the wrong place: its
    // moment then does work the spring does not store). Deepest, not closest: an edge crossing a
    // slanted face's two side edges is as close to the one it passes outside as to the one it
    // presses into, and a pick between them by a hair flipped the point from end to end
    struct EdgePair {
        int a = -1, b = -1;
        double depth = 0.0;
        Vec3 axis = Vec3::Zero();   // unit, pushes A away from B
    };
    std::array<EdgePair, 144> pairs;   // every non-parallel pair of the 12 × 12, on the stack
    int count = 0;
    double edge_depth = kInf;
    for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j) {
            Vec3 da = ca[kEdges[i][1]] - ca[kEdges[i][0]];
            Vec3 db = cb[kEdges[j][1]] - cb[kEdges[j][0]];
            Vec3 axis = da.cross(db);
            if (axis.norm() < 1e-6 * da.norm() * db.norm()) continue;   // parallel edges
            axis.normalize();
            double lo_a, hi_a, lo_b, hi_b;
            project(ca, axis, lo_a, hi_a);
            project(cb, axis, lo_b, hi_b);
            double push_a_up = hi_b - lo_a, push_a_down = hi_a - lo_b;
            if (push_a_up < 0 || push_a_down < 0) return {};
            double depth = std::min(push_a_up, push_a_down);
            pairs[size_t(count++)] = {i, j, depth, push_a_up <= push_a_down ? axis : Vec3(-axis)};
            edge_depth = std::min(edge_depth, depth);
        }
    int edge_a = -1;
    Vec3 edge_axis = Vec3::Zero(), edge_pa = Vec3::Zero(), edge_pb = Vec3::Zero();
    // (pb − pa)·axis: how far A's point lies inside B's along the axis (the same for any points of
    // the two edges' lines); a tie within round-off goes to the pair whose segments come closest
    double edge_press = -kInf, edge_gap = kInf;
    for (int k = 0; k < count; ++k) {
        const EdgePair& e = pairs[size_t(k)];
        if (e.depth > edge_depth + 1e-9 * size) continue;
        Vec3 pa, pb;
        closest_points(ca[kEdges[e.a][0]], ca[kEdges[e.a][1]], cb[kEdges[e.b][0]], cb[kEdges[e.b][1]], pa, pb);
        const double press = (pb - pa).dot(e.axis), gap = (pa - pb).norm();
        if (press > edge_press + 1e-9 * size || (press > edge_press - 1e-9 * size && gap < edge_gap)) {
            edge_press = std::max(edge_press, press);
            edge_gap = gap;
            edge_a = e.a;
            edge_axis = e.axis;
            edge_pa = pa;
            edge_pb = pb;
        }
    }

    // the reference face's contacts: the incident face (the other solid's face most opposed to
    // the reference normal) clipped by the reference face's sides, its points below the face
    auto face_contacts = [&] {
        const Solid& x = reference_on_a ? a : b;
        const Solid& y = reference_on_a ? b : a;
        const Face& ref = x.faces[reference];
        int incident = 0;
        for (int f = 1; f < 6; ++f)
            if (y.faces[f].normal.dot(ref.normal) < y.faces[incident].normal.dot(ref.normal)) incident = f;
        std::vector<Vec3> poly(y.faces[incident].corners.begin(), y.faces[incident].corners.end());
        for (int k = 0; k < 4 && !poly.empty(); ++k) {
            const Vec3& p0 = ref.corners[k];
            const Vec3& p1 = ref.corners[(k + 1) % 4];
            Vec3 s = (p1 - p0).cross(ref.normal);
            if (s.dot(ref.centre - p0) > 0) s = -s;
            poly = clip(poly, s.normalized(), p0);
        }
        std::vector<HexContact> out;
        const Vec3 normal = reference_on_a ? Vec3(-ref.normal) : ref.normal;
        for (const Vec3& p : poly) {
            double depth = ref.normal.dot(ref.centre - p);
            if (depth < 0) continue;
            out.push_back({p + 0.5 * depth * ref.normal, normal, depth});
        }
        return largest_subset(out, max_points);
    };

    // faces win unless an edge pair overlaps clearly less (the usual 5 % bias of box colliders),
    // and even then where the face's own points are no deeper than the edge pair's overlap: an
    // edge of one block lying across a face of the other is a line of contact, which one point at
    // an end of it would carry on one side only (the blocks' far corners, outside the contact,
    // can make the face axis look deeper than it is)
    if (edge_a >= 0 && edge_depth < 0.95 * face_depth - 1e-9 * size) {
        std::vector<HexContact> faces = face_contacts();
        double deepest = 0.0;
        for (const auto& c : faces) deepest = std::max(deepest, c.depth);
        if (!faces.empty() && deepest <= edge_depth + 1e-9 * size) return faces;
        return {{0.5 * (edge_pa + edge_pb), edge_axis, edge_depth}};
    }
    return face_contacts();
}

}  // namespace cairn
