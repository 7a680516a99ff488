#include "contact_pair.hpp"

#include <algorithm>
#include <cmath>

#include "contact.hpp"
#include "dem/deformable/hex8.hpp"

namespace cairn::dem {

namespace {

double reduced_mass(const Block& a, const Block& b) {
    if (a.fixed) return b.body.mass;
    if (b.fixed) return a.body.mass;
    return a.body.mass * b.body.mass / (a.body.mass + b.body.mass);
}

// the element under boundary face f: the face's nodes' lowest grid index on each axis, held
// inside the mesh (a face on a high side belongs to the last element along that axis)
int face_element(const Mesh& m, int f) {
    const int nx = m.divisions[0], ny = m.divisions[1];
    std::array<int, 3> lo{1 << 30, 1 << 30, 1 << 30};
    for (int n : m.faces[f]) {
        const int i = n % (nx + 1), j = (n / (nx + 1)) % (ny + 1), k = n / ((nx + 1) * (ny + 1));
        lo = {std::min(lo[0], i), std::min(lo[1], j), std::min(lo[2], k)};
    }
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], m.divisions[a] - 1);
    return lo[0] + nx * (lo[1] + ny * lo[2]);
}

}  // namespace

namespace {

// the target rule with the two sides' outward normals at hand (only the last tie needs them)
bool is_target_given(const std::vector<Block>& blocks, int h, int hit_side, int t, int target_side, const Vec3& nh,
                     const Vec3& nt, const TieMemory* ties = nullptr) {
    double ah = blocks[h].side_area[hit_side], at = blocks[t].side_area[target_side];
    double tol = 1e-9 * std::max(ah, at);
    if (at > ah + tol) return true;
    if (ah > at + tol) return false;
    if (blocks[t].fixed != blocks[h].fixed) return blocks[t].fixed;
    double vt = blocks[t].volume, vh = blocks[h].volume;
    if (std::abs(vt - vh) > 1e-9 * std::max(vt, vh)) return vt > vh;
    // a tie in contact keeps the roles it took at first touch
    if (const int role = ties ? ties->role(h, hit_side, t, target_side) : 0) return role > 0;
    // equal sides of equal blocks: by geometry, never by index or name. m = n_t − n_h changes
    // sign when the two swap; its first component along z, x, y of at least half its length
    // decides (the lower block of a stack is the target; side by side, the one on the −x side)
    const Vec3 m = nt - nh;
    const double half = 0.5 * m.norm();
    for (int axis : {2, 0, 1})
        if (std::abs(m[axis]) >= half) return m[axis] > 0.0;
    return t < h;   // unreachable: some component of a vector is at least 1/√3 of its length
}

}  // namespace

int TieMemory::role(int h, int hs, int t, int ts) const {
    // a block's few entries scanned (a brick in a wall touches some ten others)
    auto has = [&](int a, int as, int b, int bs) {
        if (a < 0 || size_t(a) + 1 >= first.size()) return false;
        for (int i = first[size_t(a)]; i < first[size_t(a) + 1]; ++i) {
            const auto& k = kept[size_t(i)];
            if (k[1] == as && k[2] == b && k[3] == bs) return true;
        }
        return false;
    };
    if (kept.empty()) return 0;
    if (has(h, hs, t, ts)) return 1;
    if (has(t, ts, h, hs)) return -1;
    return 0;
}

void TieMemory::index(size_t blocks) {
    std::sort(kept.begin(), kept.end());
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
    first.assign(blocks + 1, 0);
    for (const auto& k : kept) ++first[size_t(k[0]) + 1];
    for (size_t b = 0; b < blocks; ++b) first[b + 1] += first[b];
}

bool tie_by_geometry(const std::vector<Block>& blocks, int h, int hit_side, int t, int target_side) {
    const double ah = blocks[h].side_area[hit_side], at = blocks[t].side_area[target_side];
    const double vt = blocks[t].volume, vh = blocks[h].volume;
    return std::abs(at - ah) <= 1e-9 * std::max(ah, at) && blocks[t].fixed == blocks[h].fixed &&
           std::abs(vt - vh) <= 1e-9 * std::max(vt, vh);
}

bool near_tie_switch(const Vec3& nh, const Vec3& nt) {
    const Vec3 m = nt - nh;
    const double half = 0.5 * m.norm();
    for (int a = 0; a < 3; ++a)
        if (std::abs(std::abs(m[a]) - half) < 0.1 * half) return true;
    return false;
}

bool may_be_target(const std::vector<Block>& blocks, int h, int hit_side, int t, int target_side, const Vec3& nh,
                   const Vec3& nt, double turn, const TieMemory* ties) {
    const bool by_geometry = tie_by_geometry(blocks, h, hit_side, t, target_side);
    // a kept tie is the target until its sides part; then the geometric rule's bound below holds
    if (by_geometry && ties && ties->role(h, hit_side, t, target_side) > 0) return true;
    const bool rule = is_target_given(blocks, h, hit_side, t, target_side, nh, nt);
    if (rule || !by_geometry) return rule;   // areas, fixed and volumes do not change
    // the geometric rule said no: it holds as long as each component of m = n_t − n_h (each
    // moves by at most `turn`, half its length by turn/2) stays clear of the thresholds it met
    const Vec3 m = nt - nh;
    const double half = 0.5 * m.norm(), d = 2.0 * turn;
    for (int axis : {2, 0, 1}) {
        const double a = std::abs(m[axis]);
        if (a >= half) return !(a - half > d && m[axis] < -d);   // the deciding axis: clear of half and of 0
        if (a > half - d) return true;                            // might become the deciding axis
    }
    return true;
}

bool is_target(const std::vector<Block>& blocks, int h, int hit_side, int t, int target_side) {
    return is_target_given(blocks, h, hit_side, t, target_side,
                           quad_normal(blocks[h].side_quad(hit_side), Vec2::Zero()),
                           quad_normal(blocks[t].side_quad(target_side), Vec2::Zero()));
}

SideFrames SideFrames::of(const Block& b) {
    SideFrames f;
    if (!b.deformable) {
        // rigid: the block-frame sides turned as its nodes were (update_nodes)
        for (int k = 0; k < 6; ++k) {
            f.normal[size_t(k)] = b.rotation * b.side_normal_local[size_t(k)];
            f.centre[size_t(k)] = b.body.x + b.rotation * b.side_centre_local[size_t(k)];
        }
        return f;
    }
    for (int k = 0; k < 6; ++k) {
        const Quad q = b.side_quad(k);
        f.normal[k] = quad_centre_normal(q);
        f.centre[k] = 0.25 * (q[0] + q[1] + q[2] + q[3]);
    }
    return f;
}

void PairGeometry::set(const std::vector<Block>& blocks, const std::vector<SideFrames>& frames, int h, int t, bool paper) {
    hit = h;
    target = t;
    blocks_ = &blocks;
    hit_normal_ = &frames[h].normal;
    faces_done_.fill(0);
    const Block& tb = blocks[t];
    normal = frames[t].normal;
    centre = frames[t].centre;
    if (paper) {
        const std::array<Vec3, 6>& hn = frames[h].normal;
        for (int s = 0; s < 6; ++s) {
            double best = 0.0;
            best_side[s] = -1;
            for (int f = 0; f < 6; ++f) {
                const double d = hn[f].dot(normal[s]);
                if (d < best) best = d, best_side[s] = f;
            }
            target_ok[s] = best_side[s] >= 0 && is_target_given(blocks, h, best_side[s], t, s, hn[best_side[s]], normal[s]);
        }
    }
    // a hitting point up to 1e-4 of the edge outside a side plane still counts as over the
    // target side: flush edges (stacked blocks) stay in contact as they bulge
    flush_tol = 1e-4 * tb.min_edge;
    closer_tol = 0.25 * tb.min_edge;
}

const std::array<char, 6>& PairGeometry::faces(int f) {
    auto& row = faces_[size_t(f)];
    if (faces_done_[size_t(f)]) return row;
    faces_done_[size_t(f)] = 1;
    const Vec3& nh = (*hit_normal_)[size_t(f)];
    // a side within 1e-3 rad of perpendicular casts a shadow under 1e-3 of its height: left out,
    // so that rounding never makes a side standing on the target a hitting side
    for (int s = 0; s < 6; ++s)
        row[size_t(s)] = nh.dot(normal[s]) < -1e-3 && is_target_given(*blocks_, hit, f, target, s, nh, normal[s], ties);
    return row;
}

std::array<double, 2> dashpot_per_area(const ContactLaw& law, const Block& hb, const Block& tb, int hit_side) {
    if (law.damping_rule == ContactDampingRule::time) return {law.damping * law.kn, law.damping * law.ks};
    if (law.damping_rule == ContactDampingRule::ratio) {
        const double m = reduced_mass(hb, tb), area = hb.side_area[hit_side];
        return {2.0 * law.damping * std::sqrt(law.kn * m / area), 2.0 * law.damping * std::sqrt(law.ks * m / area)};
    }
    return {0.0, 0.0};
}

void spread(Block& b, int k, const Vec2& xi, const Vec3& force) {
    auto w = quad_weights(xi);
    for (int i = 0; i < 4; ++i) b.f[b.mesh.faces[k][i]] += w[i] * force;
}

NodeWeights node_weights(const Block& b, int face, const Vec3& x) {
    NodeWeights nw;
    if (!b.deformable) {
        // rigid: any affine weights reproduce the force and its moment; 4 corners of the block
        const Mesh& m = b.mesh;
        const int n0 = m.node(0, 0, 0), n1 = m.node(1, 0, 0), n2 = m.node(0, 1, 0), n3 = m.node(0, 0, 1);
        const Vec3 l = b.corner_inverse * (x - b.x[n0]);   // the corner frame's inverse (update_nodes)
        nw.count = 4;
        nw.node = {n0, n1, n2, n3};
        nw.w = {1.0 - l.sum(), l[0], l[1], l[2]};
        return nw;
    }
    // deformable: Newton inversion of the trilinear map of the element under the face
    const int e = face_element(b.mesh, face);
    const auto& en = b.mesh.elements[e];
    Vec3 xi = Vec3::Zero();
    for (int it = 0; it < 10; ++it) {
        const auto n = hex8_shape(xi);
        const Mat83 dn = hex8_dshape(xi);
        Vec3 r = -x;
        Mat3 j = Mat3::Zero();
        for (int a = 0; a < 8; ++a) {
            r += n[a] * b.x[en[a]];
            j += b.x[en[a]] * dn.row(a);
        }
        const Vec3 step = j.lu().solve(r);
        xi -= step;
        if (step.squaredNorm() < 1e-26) break;
    }
    const auto n = hex8_shape(xi);
    nw.count = 8;
    for (int a = 0; a < 8; ++a) nw.node[a] = en[a], nw.w[a] = n[a];
    return nw;
}

namespace {
// ∂N_i/∂ξ, ∂N_i/∂η of a face's bilinear weights (quad_weights) at its centre, times 4
const double kSign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
}  // namespace

// The weights of the 4 nodes of a deformable target face q (the face's nodes `nodes`) whose normal
// forces are the gradient of the stored energy for a normal force at xs: the energy sees the face
// only through its plane (centre c, normal n at the centre), which a warp of the face does not move.
// With r = c − xs: w_i = ¼ + ∂N_i/∂ξ·((b×r)·n)/J + ∂N_i/∂η·((r×a)·n)/J, a, b the face's tangents at
// its centre, J = (a×b)·n; Σw = 1 and Σw·q = xs, so force and moment are those of a force at xs
NodeWeights plane_weights(const Quad& q, const std::array<int, 4>& nodes, const Vec3& c, const Vec3& n, const Vec3& xs) {
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();
    for (int i = 0; i < 4; ++i) {
        a += 0.25 * kSign[i][0] * q[i];
        b += 0.25 * kSign[i][1] * q[i];
    }
    const Vec3 r = c - xs;
    const double j = a.cross(b).dot(n);
    const double cb = b.cross(r).dot(n) / j, ca = r.cross(a).dot(n) / j;
    NodeWeights w;
    w.count = 4;
    for (int i = 0; i < 4; ++i) {
        w.node[size_t(i)] = nodes[size_t(i)];
        w.w[size_t(i)] = 0.25 * (1.0 + kSign[i][0] * cb + kSign[i][1] * ca);
    }
    return w;
}

ForcePair couple_as_pair(const Vec3& tau, const Vec3& line, double arm) {
    const double tn = tau.norm();
    const Vec3 t = tau / tn;
    Vec3 e = t.cross(line);
    if (e.norm() < 1e-6) e = t.cross(Vec3::UnitX());
    if (e.norm() < 1e-6) e = t.cross(Vec3::UnitY());
    e.normalize();
    const Vec3 w = e.cross(t);   // (ℓw) × (|τ|/ℓ)e = |τ|·t
    return ForcePair{0.5 * arm * w, (tn / arm) * e};
}

// barycentric coordinates of x in the triangle (x0, x1, x2), all on a plane of unit normal n
std::array<double, 3> barycentric(const Vec3& x, const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& n) {
    const double den = (x1 - x0).cross(x2 - x0).dot(n);
    const double l1 = (x - x0).cross(x2 - x0).dot(n) / den, l2 = (x1 - x0).cross(x - x0).dot(n) / den;
    return {1.0 - l1 - l2, l1, l2};
}

void add_triangle_weights(const std::array<Vec3, 3>& t, const std::array<Vec2, 3>& xi, const Vec3& x, const Vec3& n,
                          double scale, std::array<double, 4>& w) {
    const auto l = barycentric(x, t[0], t[1], t[2], n);
    for (int i = 0; i < 3; ++i) {
        const auto nw = quad_weights(xi[size_t(i)]);
        for (int a = 0; a < 4; ++a) w[size_t(a)] += scale * l[size_t(i)] * nw[size_t(a)];
    }
}

NodeWeights face_node_weights(const Block& b, int face, const std::array<double, 4>& w) {
    NodeWeights nw;
    nw.count = 4;
    for (int a = 0; a < 4; ++a) nw.node[size_t(a)] = b.mesh.faces[face][size_t(a)], nw.w[size_t(a)] = w[size_t(a)];
    return nw;
}

}  // namespace cairn::dem
