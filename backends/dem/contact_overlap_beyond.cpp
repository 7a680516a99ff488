#include "contact_overlap_beyond.hpp"

#include <cmath>

#include "contact_overlap_edge.hpp"

namespace cairn::dem {

OverlapIntegrals integrate_beyond(const ClipPolygon& poly, const Vec3& c, const Vec3& n, const Affine& depth) {
    if (poly.n < 3) return OverlapIntegrals{};
    // projected vertices, their heights behind the plane and their depths
    std::array<Vec3, ClipPolygon::kMaxVertices> x;
    std::array<double, ClipPolygon::kMaxVertices> h, d;
    for (int i = 0; i < poly.n; ++i) {
        h[size_t(i)] = n.dot(c - poly.p[size_t(i)]);
        x[size_t(i)] = poly.p[size_t(i)] + h[size_t(i)] * n;
        d[size_t(i)] = depth(poly.p[size_t(i)]);
    }
    // the polygon's points are affine in the projected ones
    return fan_integrals(x.data(), h.data(), d.data(), poly.p.data(), poly.n, n);
}

double apply_beyond(const BeyondCell& in, Block& hb, int f, Block& tb, int tf, std::vector<SubForce>* kept) {
    const PairGeometry& g = *in.g;
    const Quad& face = *in.hit_face;
    const bool split = in.parts > 1;
    // a force on both blocks at one point; `normal` only names its normal part in the output (the
    // side it pushes on), both parts act at the same points
    auto put = [&](const NodeWeights& wh, const NodeWeights& wt, const Vec3& force, const Vec3& normal) {
        SubForce::put(kept, wh, wt, in.scale * force, normal, wh, wt, hb, tb);
    };
    // the hitting face's weights of a point of piece k: on a triangle, its barycentric weights,
    // each corner spread by the face's bilinear weights
    auto hit_weights = [&](int k, const Vec3& x) {
        if (!split) return node_weights(hb, f, x);
        const ClipPolygon& t = (*in.pieces)[size_t(k)];
        const Vec3 tn = (t.p[1] - t.p[0]).cross(t.p[2] - t.p[0]).normalized();
        std::array<double, 4> w{};
        add_triangle_weights({t.p[0], t.p[1], t.p[2]}, in.piece_xi[size_t(k)], x, tn, 1.0, w);
        return face_node_weights(hb, f, w);
    };
    // the target's weights of a force at x along the normal of the target face (side < 0) or of side o
    auto target_weights = [&](const Vec3& x, int side) {
        if (!tb.deformable) return node_weights(tb, tf, x);
        if (side < 0) return plane_weights(*in.target_face, tb.mesh.faces[tf], in.c, in.n, x);
        // o's plane is that of its corners (SideFrames)
        const size_t o = size_t(side);
        return plane_weights(tb.side_quad(side), tb.mesh.side_corners[o], g.centre[o], g.normal[o], x);
    };
    // the depth beyond capped cut k, d_B = (1 + κ)(d_o + reach) − κ·d_s: behind its side o plus
    // the face's reach behind o, less κ times the depth past the cut
    constexpr double kappa = kBeyondTaper;
    auto beyond_depth = [&](int k) {
        const Vec3& no = g.normal[size_t(in.caps[k].side)];
        const double co = no.dot(g.centre[size_t(in.caps[k].side)]);
        const double reach = co - no.dot(face[size_t(in.caps[k].corner)]);
        return Affine{-(1.0 + kappa) * no + kappa * in.n, (1.0 + kappa) * (co + reach) - kappa * in.n.dot(in.c)};
    };
    double stored = 0.0;
    std::array<Affine, kMaxSideConstraints> cons;
    for (int q = 0; q < in.side_count; ++q) {
        if (in.caps[q].corner < 0) continue;
        const int o = in.caps[q].side;
        const Vec3& no = g.normal[size_t(o)];
        const Affine depth = beyond_depth(q);
        // beyond cut q, where o's depth is the least of the capped ones, inside every other constraint
        for (int k = 0; k < in.count; ++k) {
            cons[size_t(k)] = in.cons[k];
            if (k == q) cons[size_t(k)] = Affine{-in.cons[k].a, -in.cons[k].b};
            else if (k < in.side_count && in.caps[k].corner >= 0) {
                const Affine other = beyond_depth(k);
                cons[size_t(k)] = Affine{other.a - depth.a, other.b - depth.b};
            }
        }
        double d1 = 0.0;   // ∫d_B dA over the cell, m³
        for (int part = 0; part < in.parts; ++part) {
            ClipPolygon poly = (*in.pieces)[size_t(part)];
            for (int k = 0; k < in.count && poly.n >= 3; ++k) clip(poly, cons[size_t(k)], k);
            if (poly.n >= 3) clip(poly, depth, in.count);   // d_B ≥ 0
            // no vertex strictly beyond the cut: nothing of it is (a face exactly on the cut's
            // plane lies on both sides of it, and counts before it)
            bool past = false;
            for (int i = 0; i < poly.n; ++i) past = past || in.cons[q](poly.p[size_t(i)]) < 0.0;
            if (poly.n < 3 || !past) continue;
            const OverlapIntegrals r = integrate_beyond(poly, in.c, in.n, depth);
            if (!(r.d1 > 0.0) || !(r.area > 0.0)) continue;
            stored += 0.5 * in.kn * r.d2;
            d1 += r.d1;
            // −kn·d_B·∇d_B at each point: at the depth-weighted centre of the points, its part
            // along o's normal and its part along the target face's on the target's weights of each
            const Vec3 xb = r.pressure_centre();   // its moment is over the face's own points
            const NodeWeights wh = hit_weights(part, xb);
            put(wh, target_weights(xb, o), (1.0 + kappa) * in.kn * r.d1 * no, no);
            put(wh, target_weights(xb, -1), -kappa * in.kn * r.d1 * in.n, in.n);
            // a rigid face's projected area on the target plane changes as it turns: the couple
            // ½kn·n × ∫d_B²·∇h dA (∇h the gradient of the face's depth behind the plane), as a
            // pair of opposite forces (the target takes the opposite couple)
            const Vec3 tau = 0.5 * in.kn * in.n.cross(r.tilt);
            if (!split && tau.norm() > 0.0) {
                const ForcePair pair = couple_as_pair(tau, in.n, hb.min_edge);
                for (const double side : {1.0, -1.0}) {
                    const Vec3 x = xb + side * pair.offset;
                    put(node_weights(hb, f, x), node_weights(tb, tf, x), side * pair.force, in.n);
                }
            }
            // where the region ends on a constraint fixed to the target with depth: the edge
            // forces (not on the capped cuts, where d_B joins d_s or another d_B, nor where d_B = 0)
            for (int i = 0; i < poly.n; ++i) {
                const int cut = int(poly.by[size_t(i)]) - 1;
                if (cut < 0 || cut >= in.count || cut == in.side_count) continue;
                if (cut < in.side_count && in.caps[cut].corner >= 0) continue;
                const EdgeForce e = edge_force(poly, i, in.c, in.n, cons[size_t(cut)], r.slope, in.kn, &depth);
                // (on the target at the point itself: it pushes along the plane, see the cell's edges)
                if (!e.force.isZero(0.0))
                    put(hit_weights(part, e.point), node_weights(tb, tf, e.point), e.force, e.force.normalized());
            }
        }
        if (!(d1 > 0.0)) continue;
        // the reach moves with the deepest corner: (1 + κ)·kn∫d_B along o's normal there
        const Vec3& corner = face[size_t(in.caps[q].corner)];
        NodeWeights wc;
        if (!split) wc = node_weights(hb, f, corner);
        else {
            std::array<double, 4> w{};
            w[size_t(in.caps[q].corner)] = 1.0;
            wc = face_node_weights(hb, f, w);
        }
        put(wc, target_weights(corner, o), (1.0 + kappa) * in.kn * d1 * no, no);
    }
    return stored;
}

}  // namespace cairn::dem
