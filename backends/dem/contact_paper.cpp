// The paper's node-to-face scheme (contact.scheme = "paper"): hitting points of a virtual grid.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "contact.hpp"

namespace cairn::dem {

namespace {

// the weights that put a force at natural coordinates xi of boundary face k on its 4 nodes
NodeWeights face_weights(const Block& b, int k, const Vec2& xi) {
    NodeWeights w;
    w.count = 4;
    const auto q = quad_weights(xi);
    for (int i = 0; i < 4; ++i) {
        w.node[size_t(i)] = b.mesh.faces[size_t(k)][size_t(i)];
        w.w[size_t(i)] = q[size_t(i)];
    }
    return w;
}

// Anchor::side of a point inside the target that came in past the edge of the side it would act on
constexpr int kCameInElsewhere = -2;

}  // namespace

void ContactSet::evaluate_paper(std::vector<Block>& blocks, double dt, long begin, long end, bool keep_forces) {
    // the geometry of the (hitting, target) pair of the candidates at hand
    PairGeometry g;
    std::array<ParallelogramFrame, 6> frames;   // rigid parallelogram target sides: closed-form projection
    for (long ci = begin; ci < end; ++ci) {
        Candidate& c = candidates_[size_t(ci)];
        ContactTotals& tot = c.totals;
        Block& hb = blocks[c.hit_block];
        Block& tb = blocks[c.target_block];
        // an anchor given up releases its shear spring: that energy is dissipated
        auto reset = [&](Anchor& a) {
            tot.dissipated += a.energy;
            const PointTrack track = a.track;
            a = Anchor{};
            a.track = track;
        };
        if (g.update(blocks, frames_, c.hit_block, c.target_block, true)) {
            for (int s = 0; s < 6; ++s)
                frames[s] = tb.mesh.side_grid[s].size() == 1 ? ParallelogramFrame::of(tb.side_quad(s)) : ParallelogramFrame{};
        }
        const int hit_side = hb.mesh.face_side[c.hit_face];
        // a face whose side is the hitting side of no target side cannot act: clear its anchors
        if (!g.acts(hit_side)) {
            for (auto& a : c.anchors) reset(a);
            continue;
        }
        const Quad hq = hb.face_quad(c.hit_face);
        const auto& pts = hb.hits[c.hit_face];
        // damping coefficients per unit tributary area, N·s/m³
        const auto [cn_area, ct_area] = dashpot_per_area(law_, hb, tb, hit_side);
        for (size_t k = 0; k < pts.size(); ++k) {
            Anchor& anchor = c.anchors[k];
            const PointTrack last = anchor.track;   // the previous evaluation
            anchor.track = PointTrack{};
            const Vec3 xp = quad_point(hq, pts[k].xi);
            // the point acts on the allowed target side it lies deepest behind, if it is inside
            // the target block (behind every side plane, flush within rounding) and no other
            // side is clearly closer (it would be entering through that side instead); a point
            // new to the side must also be entering through it (below)
            double dist[6];
            int side = -1;
            for (int s = 0; s < 6; ++s) {
                dist[s] = g.normal[s].dot(xp - g.centre[s]);
                if (g.best_side[s] == hit_side && g.target_ok[s] && (side < 0 || dist[s] > dist[side])) side = s;
            }
            // the signed depth behind the side it acts (or would act) on: its gap when outside
            const int depth_side = anchor.side >= 0 ? anchor.side : side;
            if (depth_side >= 0) anchor.track.depth = -dist[depth_side];
            // a point that leaves contact in this step: its last dashpot force did work over the
            // step, and its spring acted only for the part of the step before the gap opened
            // (the fraction φ from its depth at both ends, the depth linear over the step): the
            // end-of-step half kick takes back (1 − φ) of the spring's impulse (docs/dem.md, Energy)
            auto leave = [&]() {
                if (last.face < 0) return;   // not in contact at the last evaluation
                const NodeWeights wh = face_weights(hb, c.hit_face, pts[k].xi), wt = face_weights(tb, last.face, last.xi);
                const double closing = -(wh.velocity(hb) - wt.velocity(tb)).dot(last.normal);
                tot.dissipated += 0.5 * anchor.fd * closing * dt;
                const double d0 = last.depth, d1 = anchor.track.depth;
                if (!(last.fel > 0.0) || !(d0 > 0.0) || !(d1 <= 0.0)) return;   // no push, left sideways, or no known gap
                const Vec3 f = (d0 / (d0 - d1) - 1.0) * last.fel * last.normal;
                c.events.push_back({c.hit_block, wh, f});
                c.events.push_back({c.target_block, wt, -f});
            };
            bool inside = side >= 0 && dist[side] < 0.0;
            for (int s = 0; inside && s < 6; ++s)
                if (s != side && (dist[s] > g.flush_tol || dist[s] > dist[side] + g.closer_tol)) inside = false;
            if (!inside) {
                // a point that came in past the edge of its side stays out while inside the target
                const bool blocked = anchor.side == kCameInElsewhere && g.within(dist);
                leave();
                reset(anchor);
                if (blocked) anchor.side = kCameInElsewhere;
                continue;
            }
            // the target face: the side's boundary face under the point (rigid: the side itself)
            const ParallelogramFrame& frame = frames[side];
            int face = tb.mesh.side_grid[side][0];
            if (tb.mesh.side_grid[side].size() > 1) face = tb.face_at(side, project(tb.side_quad(side), xp).xi);
            const Quad tq = tb.face_quad(face);
            Projection pr = frame.valid ? frame.project(xp) : project(tq, xp);
            const Vec3& n = pr.normal;
            const double depth = n.dot(pr.point - xp);
            if (!(depth > 0.0)) {
                anchor.track.depth = depth;
                leave();
                reset(anchor);
                continue;
            }
            // relative velocity of the hitting point against the target material point
            Vec3 vh = Vec3::Zero(), vt = Vec3::Zero();
            auto wh = quad_weights(pts[k].xi), wt = quad_weights(pr.xi);
            for (int i = 0; i < 4; ++i) {
                vh += wh[i] * hb.v[hb.mesh.faces[c.hit_face][i]];
                vt += wt[i] * tb.v[tb.mesh.faces[face][i]];
            }
            const Vec3 vrel = vh - vt;
            // a point not acting on this side at the last evaluation must come in through it:
            // found first nearer to another side plane (by more than this step's travel) it came
            // in through that one, past the edge of this side, and does not act for as long as it
            // stays inside the target (docs/dem.md)
            if (anchor.side != side && (anchor.side == kCameInElsewhere || !g.enters_through(dist, side, vrel.norm() * dt))) {
                leave();
                reset(anchor);
                anchor.side = kCameInElsewhere;
                continue;
            }
            const double depth_ratio = depth / std::min(hb.min_edge, tb.min_edge);
            if (depth_ratio > tot.worst_depth) tot.worst_depth = depth_ratio, tot.worst_hit = c.hit_block, tot.worst_target = c.target_block;
            const double a = pts[k].area;
            const double closing = -vrel.dot(n);
            // normal: penalty spring plus dashpot, never pulling
            const double fn_el = law_.kn * a * depth;
            double fn = std::max(0.0, fn_el + cn_area * a * closing);
            // the dashpot's work over the step as the leapfrog step does it: the mean of its
            // forces at both ends times the step's closing (booking the end force alone is
            // first order in dt)
            const double fd = fn - fn_el, fd_old = anchor.fd;
            const Vec3 fds_old = anchor.fds;
            Vec3 fds = Vec3::Zero();
            tot.dissipated += 0.5 * (fd_old + fd) * closing * dt;
            tot.stored += 0.5 * fn_el * depth;
            // shear: elastic from the stick anchor, capped at μ·Fn
            Vec3 fs = Vec3::Zero();
            if (law_.ks > 0.0 && fn > 0.0) {
                if (anchor.side != side || anchor.face < 0) {
                    reset(anchor);
                    anchor.side = side;
                    anchor.face = face;
                    anchor.xi0 = pr.xi;
                }
                const Vec3 x0_old = frame.valid ? frame.point(anchor.xi0) : quad_point(tb.face_quad(anchor.face), anchor.xi0);
                Vec3 u = pr.point - x0_old;
                u -= u.dot(n) * n;
                Vec3 vt_rel = vrel - vrel.dot(n) * n;
                const double ks_a = law_.ks * a;
                Vec3 f_el = -ks_a * u;
                const double cap = slip_ ? law_.friction * fn : std::numeric_limits<double>::max();
                if (f_el.norm() > cap) {
                    // slip: the spring is capped at μ·Fn and its anchor follows; no shear dashpot
                    fs = cap * f_el / f_el.norm();
                    Projection moved = frame.valid ? frame.project(pr.point + fs / ks_a) : project(tq, pr.point + fs / ks_a, pr.xi);
                    anchor.face = face;
                    anchor.xi0 = moved.xi;
                    // friction work over the step: the leapfrog step does the work of a force
                    // by the trapezoid rule (the mean of its values at both ends times the
                    // step's displacement), which for the spring is ½ks·A·(u_old + u_new)·Δ;
                    // less the change of its energy, that leaves ½ks·A·(u_old + u_new)·slip
                    const Vec3 u_new = -fs / ks_a;
                    const Vec3 u_old = anchor.u - anchor.u.dot(n) * n;
                    tot.dissipated += 0.5 * ks_a * (u_old + u_new).dot(u - u_new);
                    anchor.u = u_new;
                    anchor.energy = 0.5 * fs.squaredNorm() / ks_a;
                } else {
                    // stick: spring plus shear dashpot, the dashpot trimmed so the sum stays ≤ μ·Fn
                    fs = f_el - ct_area * a * vt_rel;
                    if (fs.norm() > cap) fs *= cap / fs.norm();
                    anchor.energy = 0.5 * u.squaredNorm() * ks_a;
                    anchor.u = u;
                    fds = fs - f_el;
                    tot.dissipated -= 0.5 * (fds_old + fds).dot(vt_rel) * dt;
                }
                tot.stored += anchor.energy;
            } else {
                reset(anchor);
                anchor.side = side;   // no shear spring, but the point stays in contact with this side
            }
            anchor.fd = fd;
            anchor.fds = fds;
            anchor.track = PointTrack{depth, fn > 0.0 ? fn_el : 0.0, n, face, pr.xi};
            // a point that enters contact in this step pushed only for the part φ of the step
            // after its gap closed: the end-of-step half kick gives φ of the spring's force, so
            // the step's impulse and work are those of that part (docs/dem.md, Energy); the
            // next step starts from the whole force
            if (fn > 0.0 && last.depth <= 0.0) {
                const Vec3 f = (depth / (depth - last.depth) - 1.0) * fn_el * n;
                c.events.push_back({c.hit_block, face_weights(hb, c.hit_face, pts[k].xi), f});
                c.events.push_back({c.target_block, face_weights(tb, face, pr.xi), -f});
            }
            if (keep_forces) {
                c.forces.push_back({int(k), face, pr.xi, fn * n + fs});
            } else {
                spread(hb, c.hit_face, pts[k].xi, fn * n + fs);
                spread(tb, face, pr.xi, -(fn * n + fs));
            }
            ++tot.active;
        }
    }
}

}  // namespace cairn::dem
