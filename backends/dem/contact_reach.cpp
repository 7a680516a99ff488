#include "contact_reach.hpp"

#include <algorithm>
#include <cmath>

namespace cairn::dem {

// Where the hitting side faces o (normals opposed, whichever of the two hits), a point nearer to
// o than to s entered through o: it acts there (the hitting side hits o, the region is shared
// along the bisector) or not at all. With a tolerance there the depth behind s was measured past
// the side the point entered through: next to a joint between two voussoirs (sides meeting at
// 3.6°) the adjacent joint face was pushed along the intrados normal with 16× its penetration.
// Where the hitting side runs across o (a face flush with the edge of a face below it) the
// paper's quarter-edge tolerance stays: a point near the edge came through s, and without it a
// strip of width d along the edge would drop in and out as d changes
int side_constraints(const PairGeometry& g, int s, const Vec3& hit_normal, bool loose,
                     std::array<Affine, kMaxSideConstraints>& out, const Quad* hit_face,
                     std::array<ReachCap, kMaxSideConstraints>* caps, double motion,
                     const std::array<signed char, 6>* facing_given) {
    int k = 0;
    const Vec3& ns = g.normal[s];
    const double cs = ns.dot(g.centre[s]);
    for (int o = 0; o < 6; ++o) {
        if (o == s) continue;
        const Vec3& no = g.normal[o];
        const double co = no.dot(g.centre[o]);
        out[k++] = Affine{-no, co + g.flush_tol};
        const signed char given = facing_given ? (*facing_given)[size_t(o)] : -1;
        const bool facing = !loose && (given >= 0 ? given == 1 : hit_normal.dot(no) < -kFacingBegin);
        double tol = facing ? 0.0 : g.closer_tol;
        if (caps) (*caps)[size_t(k)] = ReachCap{};
        if (loose) {
            // the refresh's bound over any orientation: the closer tolerance; where the face may
            // be capped before the next refresh (its reach behind o, give or take `motion`, below
            // the tolerance) widened to hold the region beyond the cut too, d_s < m(d_o + r),
            // m = 1 + 1/κ, r the reach (contact_overlap_beyond.hpp); (m − 1)·flush_tol keeps
            // d_s ≤ d_o + tol inside where d_o ≥ −flush_tol
            double reach = g.closer_tol;
            if (hit_face) {
                reach = 0.0;
                for (const auto& p : *hit_face) reach = std::max(reach, co - no.dot(p));
            }
            if (reach - motion >= g.closer_tol) out[k++] = Affine{ns - no, co - cs + g.closer_tol};
            else {
                const double m = 1.0 + 1.0 / kBeyondTaper;
                const double r = std::min(g.closer_tol, reach + motion);
                out[k++] = Affine{ns - m * no, m * (co + r) + g.closer_tol + (m - 1.0) * g.flush_tol - cs};
            }
            continue;
        }
        if (!facing && hit_face) {
            // no deeper than the hitting face reaches behind o: a face that only dips behind o's
            // plane (a brick hanging over the edge of its base, its bottom sunk a millimetre into
            // the base's top) entered through o, and the sliver of its side that lies behind o
            // must not be measured from s, a tenth of a metre away
            // (most faces reach past the tolerance at their first corner: stop there)
            double reach = 0.0;
            int deepest = -1;
            for (int i = 0; i < 4 && reach < tol; ++i) {
                const double r = co - no.dot((*hit_face)[size_t(i)]);
                if (r > reach) reach = r, deepest = i;
            }
            if (reach < tol) {
                tol = reach;
                if (caps) (*caps)[size_t(k)] = ReachCap{deepest, o};
            }
        }
        out[k++] = Affine{ns - no, co - cs + tol};
    }
    return k;
}

bool may_act(const std::vector<Block>& blocks, const std::vector<SideFrames>& frames, int h, int f, int t,
             double margin, PairGeometry& g) {
    const Block& hb = blocks[h];
    const Block& tb = blocks[t];
    g.update(blocks, frames, h, t);
    const int hit_side = hb.mesh.face_side[f];
    const Vec3& nh = frames[size_t(h)].normal[size_t(hit_side)];
    const Quad hq = hb.face_quad(f);
    // each block turns by at most kRefreshTurn (and (margin/2)/r_max): a unit normal by as much,
    // the pair's by the sum; half as much again for the refresh check's look-ahead of one step
    const double turn = 1.5 * (std::min(kRefreshTurn, 0.5 * margin / hb.r_max) + std::min(kRefreshTurn, 0.5 * margin / tb.r_max));
    // a hitting point and the target point under it drift apart by at most the margin (the
    // flush tolerance: a point of the target's flush shell is that much farther out), so an
    // affine constraint a·p + b changes by at most |a| times that
    const double reach = margin + g.flush_tol;
    std::array<Affine, kMaxSideConstraints> cons;
    // a constraint that none of the face's corners meets within the reach rules the side out
    auto missed = [&](int k0, int k1) {
        for (int k = k0; k < k1; ++k) {
            const double slack = cons[size_t(k)].a.norm() * reach;
            bool none = true;
            for (const auto& p : hq) none = none && cons[size_t(k)](p) < -slack;
            if (none) return true;
        }
        return false;
    };
    for (int s = 0; s < 6; ++s) {
        const Vec3& ns = g.normal[size_t(s)];
        if (!(nh.dot(ns) < -1e-3 + turn)) continue;
        if (!may_be_target(blocks, h, hit_side, t, s, nh, ns, turn, g.ties)) continue;
        const int side_count = side_constraints(g, s, nh, true, cons, &hq, nullptr, reach);
        if (missed(0, side_count)) continue;   // the side's planes first: most faces stop here
        int nc = side_count;
        if (tb.mesh.side_grid[size_t(s)].size() == 1) {
            // the side is one face: behind it and over it (inside each of its edges)
            const Quad tq = tb.face_quad(tb.mesh.side_grid[size_t(s)][0]);
            const Vec3& ct = g.centre[size_t(s)];
            cons[size_t(nc++)] = Affine{-ns, ns.dot(ct)};
            for (int i = 0; i < 4; ++i) {
                const Vec3 a0 = tq[size_t(i)] - ns.dot(tq[size_t(i)] - ct) * ns;
                const Vec3 a1 = tq[size_t((i + 1) % 4)] - ns.dot(tq[size_t((i + 1) % 4)] - ct) * ns;
                const Vec3 a = ns.cross(a1 - a0).normalized();
                cons[size_t(nc++)] = Affine{a, -a.dot(a0)};
            }
        }
        if (!missed(side_count, nc)) return true;
    }
    return false;
}

}  // namespace cairn::dem
