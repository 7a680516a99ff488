// The overlap scheme (contact.scheme = "overlap"): the penalty integrated over the overlap of a
// hitting face with the target faces, on n×n sub-contacts per hitting face.
#include <algorithm>
#include <array>
#include <cmath>

#include "contact.hpp"
#include "contact_overlap.hpp"
#include "contact_overlap_edge.hpp"
#include "contact_reach.hpp"

namespace cairn::dem {

namespace {

constexpr int kMaxSubdivision = 16;   // the scene reader's bound on contact.subdivision
constexpr int kMaxConstraints = kMaxSideConstraints;

}  // namespace

void ContactSet::evaluate_overlap(std::vector<Block>& blocks, double dt, long begin, long end, bool keep_forces) {
    PairGeometry g;
    const int n = std::clamp(law_.subdivision, 1, kMaxSubdivision);
    std::array<Vec3, (kMaxSubdivision + 1) * (kMaxSubdivision + 1)> grid;   // sub-cell corners
    std::array<Affine, kMaxConstraints> cons;
    for (long ci = begin; ci < end; ++ci) {
        Candidate& c = candidates_[size_t(ci)];
        ContactTotals& tot = c.totals;
        Block& hb = blocks[c.hit_block];
        Block& tb = blocks[c.target_block];
        for (auto& a : c.subs) a.seen = false;
        g.update(blocks, frames_, c.hit_block, c.target_block);
        const int hit_side = hb.mesh.face_side[c.hit_face];
        const std::array<char, 6>& faces = g.faces(hit_side);
        if (faces[0] || faces[1] || faces[2] || faces[3] || faces[4] || faces[5]) {
            const Quad hq = hb.face_quad(c.hit_face);
            Aabb hbox;
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i) grid[j * (n + 1) + i] = quad_point(hq, Vec2(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n));
            const auto [cn_area, ct_area] = dashpot_per_area(law_, hb, tb, hit_side);
            bool ready = false;   // the box: laid at the first side not missed
            for (int s = 0; s < 6; ++s) {
                if (!faces[size_t(s)]) continue;
                // the face lies in the hull of its corners: a constraint none of them meets rules
                // out every sub-cell at once (most candidate faces stop here), the side's own
                // constraints first, then each target face's
                auto missed_by = [&](const Affine* k0, const Affine* k1) {
                    for (const Affine* k = k0; k != k1; ++k) {
                        bool none = true;
                        for (const auto& p : hq) none = none && (*k)(p) < 0.0;
                        if (none) return true;
                    }
                    return false;
                };
                const int side_count = side_constraints(g, s, frames_[size_t(c.hit_block)].normal[size_t(hit_side)], false, cons);
                if (missed_by(cons.data(), cons.data() + side_count)) continue;
                if (!ready) {
                    ready = true;
                    for (const auto& p : hq) hbox.add(p);
                    hbox.inflate(tb.min_edge);   // a face may lie deep behind the target side
                }
                for (int tf : tb.mesh.side_grid[s]) {
                    const Quad tq = tb.face_quad(tf);
                    Aabb tbox;
                    for (const auto& p : tq) tbox.add(p);
                    if (!tbox.overlaps(hbox)) continue;
                    // the target face made planar: its centre, normal at the centre, corners on that plane
                    const bool whole = tb.mesh.side_grid[s].size() == 1;   // the face is the side
                    const Vec3 ct = whole ? g.centre[s] : Vec3(0.25 * (tq[0] + tq[1] + tq[2] + tq[3]));
                    const Vec3 nt = whole ? g.normal[s] : quad_normal(tq, Vec2::Zero());
                    Quad flat;
                    for (int i = 0; i < 4; ++i) flat[i] = tq[i] - nt.dot(tq[i] - ct) * nt;
                    int nc = side_count;
                    cons[nc++] = Affine{-nt, nt.dot(ct)};   // behind the face: d ≥ 0
                    // over the face: inside each edge; a face that is the whole side within the
                    // flush tolerance, as the other sides' planes (a face flush with the edge of
                    // an equal one is bounded by its own edge, which moves with it, and not by the
                    // target's, whose edge force would come and go as rounding moves one past
                    // the other: the arches' joints)
                    const double edge_tol = whole ? g.flush_tol : 0.0;
                    for (int i = 0; i < 4; ++i) {
                        const Vec3 a = nt.cross(flat[(i + 1) % 4] - flat[i]).normalized();
                        cons[nc++] = Affine{a, -a.dot(flat[i]) + edge_tol};
                    }
                    if (missed_by(cons.data() + side_count, cons.data() + nc)) continue;
                    for (int v = 0; v < n; ++v)
                        for (int u = 0; u < n; ++u) {
                            ClipPolygon poly;
                            poly.n = 4;
                            poly.p = {grid[v * (n + 1) + u], grid[v * (n + 1) + u + 1], grid[(v + 1) * (n + 1) + u + 1],
                                      grid[(v + 1) * (n + 1) + u]};
                            bool empty = false;
                            for (int k = 0; k < nc && !empty; ++k) {
                                clip(poly, cons[k], k);
                                empty = poly.n < 3;
                            }
                            if (empty) continue;
                            const OverlapIntegrals in = integrate_depth(poly, ct, nt);
                            if (!(in.d1 > 0.0) || !(in.area > 0.0)) continue;
                            double dmax = 0.0;
                            // how deep a point is in the target: its distance to the nearest
                            // side (a sliver of a face crossing a side nearly square to it may lie
                            // up to the closer tolerance behind that side, yet just under the one
                            // it entered through)
                            for (int i = 0; i < poly.n; ++i) {
                                double d = nt.dot(ct - poly.p[i]);
                                for (int o = 0; o < 6; ++o)
                                    if (o != s) d = std::min(d, g.normal[o].dot(g.centre[o] - poly.p[i]));
                                dmax = std::max(dmax, d);
                            }
                            const double depth_ratio = dmax / std::min(hb.min_edge, tb.min_edge);
                            if (depth_ratio > tot.worst_depth) tot.worst_depth = depth_ratio, tot.worst_hit = c.hit_block, tot.worst_target = c.target_block;
                            // the sub-contact's anchor, found or new
                            const int cell = v * n + u;
                            SubAnchor* anchor = nullptr;
                            for (auto& a : c.subs)
                                if (a.cell == cell && a.target_face == tf) anchor = &a;
                            const bool fresh = anchor == nullptr;
                            if (fresh) {
                                c.subs.emplace_back();
                                c.subs.back().cell = cell;
                                c.subs.back().target_face = tf;
                                anchor = &c.subs.back();
                            }
                            anchor->seen = true;
                            // the pressure centre on the target plane, moved by the tilt couple: both
                            // blocks are pushed there
                            const Vec3 xs = in.action_point();
                            const NodeWeights wh = node_weights(hb, c.hit_face, xs), wt = node_weights(tb, tf, xs);
                            const Vec3 vrel = wh.velocity(hb) - wt.velocity(tb);
                            const double closing = -vrel.dot(nt);
                            // normal: the exact integral of kn·d, plus the dashpot, never pulling
                            const double fn_el = law_.kn * in.d1;
                            const double fn = std::max(0.0, fn_el + cn_area * in.area * closing);
                            // the dashpot's work as the leapfrog step does it: the mean of
                            // its forces at both ends of the step times the step's closing
                            const double fd = fn - fn_el;
                            Vec3 fds = Vec3::Zero();
                            tot.dissipated += 0.5 * (anchor->fd + fd) * closing * dt;
                            anchor->fd = fd;
                            tot.stored += 0.5 * law_.kn * in.d2;
                            // a sub-contact that entered in this step pushed only for part of it:
                            // the end-of-step half kick gives the spring the force 2U/δ (U its
                            // energy now, δ the step's closing) whose trapezoid work is U; for a
                            // face landing flat that is φ·kn·∫d dA, φ the part of the step after
                            // the gap closed (docs/dem.md, Energy: contact events)
                            const double delta = closing * dt;
                            if (fresh && fn > 0.0 && delta > 0.0) {
                                const double f_end = std::min(fn_el, law_.kn * in.d2 / delta);
                                if (f_end < fn_el) {
                                    c.events.push_back({c.hit_block, wh, (f_end - fn_el) * nt});
                                    c.events.push_back({c.target_block, wt, (fn_el - f_end) * nt});
                                }
                            }
                            anchor->fel = fn > 0.0 ? fn_el : 0.0;
                            anchor->stored = 0.5 * law_.kn * in.d2;
                            anchor->normal = nt;
                            anchor->hit_at = wh;
                            anchor->target_at = wt;
                            Vec3 fs = Vec3::Zero();
                            if (law_.ks > 0.0 && fn > 0.0) {
                                // the shear offset grows with the relative tangential motion at the
                                // pressure centre over the step (the half-step velocity is the one
                                // the positions drifted with); laid at zero on first touch
                                const bool lay = fresh || anchor->energy < 0.0;
                                if (lay) anchor->u.setZero();
                                const Vec3 vt_rel = vrel - vrel.dot(nt) * nt;
                                Vec3 u_t = anchor->u - anchor->u.dot(nt) * nt + vt_rel * dt;
                                // the spring's stiffness ks·A follows the contact area; the offset
                                // is scaled so that a change of area neither makes nor takes spring
                                // energy (½ks·A·u² kept: u scaled by √(A_old/A)), and its growth over
                                // the step by the step's mean √A (s = √A·u grows by √A·v·dt: with
                                // √A_old alone the step's work missed the spring's energy by
                                // ½ks·(√A − √A_old)·√A·u·v·dt, first order where areas change fast)
                                Vec3 u_old = anchor->u - anchor->u.dot(nt) * nt;
                                if (!lay && anchor->area > 0.0) {
                                    const double scale = std::sqrt(anchor->area / in.area);
                                    u_old *= scale;
                                    u_t = u_old + (0.5 * (1.0 + scale)) * vt_rel * dt;
                                }
                                anchor->area = in.area;
                                const double ks_a = law_.ks * in.area;
                                const Vec3 f_el = -ks_a * u_t;
                                const double cap = law_.friction * fn;
                                if (f_el.norm() > cap) {
                                    // slip: the spring is capped at μ·Fn, the offset shrinks to match
                                    fs = cap * f_el / f_el.norm();
                                    const Vec3 u_new = -fs / ks_a;
                                    // friction work over the step (the leapfrog step does a
                                    // force's work by the trapezoid rule): ½ks·A·(u_old + u_new)·slip
                                    tot.dissipated += 0.5 * ks_a * (u_old + u_new).dot(u_t - u_new);
                                    anchor->u = u_new;
                                    anchor->energy = 0.5 * fs.squaredNorm() / ks_a;
                                } else {
                                    // stick: spring plus shear dashpot, trimmed so the sum stays ≤ μ·Fn
                                    fs = f_el - ct_area * in.area * vt_rel;
                                    if (fs.norm() > cap) fs *= cap / fs.norm();
                                    anchor->u = u_t;
                                    anchor->energy = 0.5 * ks_a * u_t.squaredNorm();
                                    fds = fs - f_el;
                                    tot.dissipated -= 0.5 * (anchor->fds + fds).dot(vt_rel) * dt;
                                }
                                tot.stored += anchor->energy;
                            } else {
                                // no normal force: the anchor is given up (re-laid at the next touch)
                                tot.dissipated += std::max(0.0, anchor->energy);
                                anchor->energy = -1.0;
                                anchor->area = 0.0;
                            }
                            anchor->fds = fds;
                            const Vec3 force = fn * nt + fs;
                            if (keep_forces) {
                                c.sub_forces.push_back({wh, wt, force, nt});
                            } else {
                                wh.add(hb, force);
                                wt.add(tb, -force);
                            }
                            // where the polygon ends on a constraint fixed to the target (a target
                            // face's edge, another side's plane) with depth, U changes as the
                            // face moves over it: the boundary term of the gradient, on both blocks
                            // at the edge's hitting points (the cell's own edges move with it, and
                            // d = 0 on the depth cut)
                            for (int i = 0; i < poly.n; ++i) {
                                const int k = int(poly.by[size_t(i)]) - 1;
                                if (k < 0 || k == side_count) continue;
                                const EdgeForce e = edge_force(poly, i, ct, nt, cons[size_t(k)], in.slope, law_.kn);
                                if (e.force.isZero(0.0)) continue;
                                const NodeWeights eh = node_weights(hb, c.hit_face, e.point), et = node_weights(tb, tf, e.point);
                                if (keep_forces) {
                                    c.sub_forces.push_back({eh, et, e.force, nt});
                                } else {
                                    eh.add(hb, e.force);
                                    et.add(tb, -e.force);
                                }
                            }
                            ++tot.active;
                        }
                }
            }
        }
        // anchors out of contact release their shear springs: that energy is dissipated
        size_t kept = 0;
        for (size_t i = 0; i < c.subs.size(); ++i) {
            const SubAnchor& a = c.subs[i];
            if (a.seen) {
                c.subs[kept++] = a;
                continue;
            }
            tot.dissipated += std::max(0.0, a.energy);
            if (a.fd == 0.0 && !(a.fel > 0.0)) continue;
            // it left in this step: its last dashpot force did work over the step, and its
            // spring pushed only until the gap opened: the end-of-step half kick takes back the
            // part of the start's force whose trapezoid work exceeds its energy U0, 2U0/|δ| − F0
            // (≤ 0; a face lifting flat: (φ − 1)·F0) (docs/dem.md, Energy: contact events)
            const double closing = -(a.hit_at.velocity(hb) - a.target_at.velocity(tb)).dot(a.normal);
            tot.dissipated += 0.5 * a.fd * closing * dt;
            const double delta = closing * dt;
            if (!(a.fel > 0.0) || !(delta < 0.0)) continue;
            const double f_end = std::max(-a.fel, 2.0 * a.stored / -delta - a.fel);
            if (f_end < 0.0) {
                c.events.push_back({c.hit_block, a.hit_at, f_end * a.normal});
                c.events.push_back({c.target_block, a.target_at, -f_end * a.normal});
            }
        }
        c.subs.resize(kept);
    }
}

}  // namespace cairn::dem
