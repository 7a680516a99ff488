#include "contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "broad_phase.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace cairn::dem {

void ContactSet::configure(const ContactLaw& law, double margin) {
    law_ = law;
    margin_ = margin;
}

bool is_target(const std::vector<Block>& blocks, int h, int hit_side, int t, int target_side) {
    double ah = blocks[h].side_area[hit_side], at = blocks[t].side_area[target_side];
    double tol = 1e-9 * std::max(ah, at);
    if (at > ah + tol) return true;
    if (ah > at + tol) return false;
    if (blocks[t].fixed != blocks[h].fixed) return blocks[t].fixed;
    double vt = blocks[t].volume, vh = blocks[h].volume;
    if (std::abs(vt - vh) > 1e-9 * std::max(vt, vh)) return vt > vh;
    return t < h;
}

void ContactSet::refresh(std::vector<Block>& blocks) {
    // the previous candidates, sorted by (hitting block, target block, face), hand their anchors on
    auto key = [](const Candidate& c) { return std::make_tuple(c.hit_block, c.target_block, c.hit_face); };
    previous_.swap(candidates_);
    candidates_.clear();
    std::sort(previous_.begin(), previous_.end(), [&](const Candidate& a, const Candidate& b) { return key(a) < key(b); });

    boxes_.resize(blocks.size());
    for (size_t i = 0; i < blocks.size(); ++i) {
        boxes_[i] = blocks[i].bounds();
        boxes_[i].inflate(0.5 * margin_);
        blocks[i].x_at_refresh = blocks[i].body.x;
        blocks[i].q_at_refresh = blocks[i].body.q;
    }
    overlapping_pairs(boxes_, order_, pairs_);
    for (auto [i, j] : pairs_) {
        if (blocks[i].fixed && blocks[j].fixed) continue;
        for (auto [h, t] : {std::pair<int, int>{i, j}, std::pair<int, int>{j, i}}) {
            for (int f = 0; f < int(blocks[h].mesh.faces.size()); ++f) {
                Aabb fb;
                for (int n : blocks[h].mesh.faces[f]) fb.add(blocks[h].x[n]);
                fb.inflate(0.5 * margin_);
                if (!fb.overlaps(boxes_[t])) continue;
                Candidate c;
                c.hit_block = h;
                c.hit_face = f;
                c.target_block = t;
                auto it = std::lower_bound(previous_.begin(), previous_.end(), c,
                                           [&](const Candidate& a, const Candidate& b) { return key(a) < key(b); });
                if (it != previous_.end() && key(*it) == key(c)) {
                    c.anchors = std::move(it->anchors);
                    c.forces = std::move(it->forces);   // keeps its capacity: no allocation in the step
                }
                c.anchors.resize(blocks[h].hits[f].size());
                candidates_.push_back(std::move(c));
            }
        }
    }
}

namespace {

// geometry of a target block's sides for one step
struct TargetSides {
    std::array<Vec3, 6> normal;   // outward unit normals
    std::array<Vec3, 6> centre;   // face centres
};

TargetSides sides_of(const Block& b) {
    TargetSides s;
    for (int k = 0; k < 6; ++k) {
        Quad q = b.side_quad(k);
        s.normal[k] = quad_normal(q, Vec2::Zero());
        s.centre[k] = 0.25 * (q[0] + q[1] + q[2] + q[3]);
    }
    return s;
}

// spread a force at natural coordinates xi of face k of block b to its nodes
void spread(Block& b, int k, const Vec2& xi, const Vec3& force) {
    auto w = quad_weights(xi);
    for (int i = 0; i < 4; ++i) b.f[b.mesh.faces[k][i]] += w[i] * force;
}

double reduced_mass(const Block& a, const Block& b) {
    if (a.fixed) return b.body.mass;
    if (b.fixed) return a.body.mass;
    return a.body.mass * b.body.mass / (a.body.mass + b.body.mass);
}

}  // namespace

ContactTotals ContactSet::apply(std::vector<Block>& blocks, double dt) {
    const long count = long(candidates_.size());
    // below a thousand hitting points a parallel region costs more than it saves (a single block
    // on its base has a few hundred): one thread then spreads the forces as it goes
    size_t points = 0;
    for (const auto& c : candidates_) points += c.anchors.size();
    if (points >= 1000) {
#pragma omp parallel
        {
            long lo = 0, hi = count;
#ifdef _OPENMP
            // contiguous chunks: no two threads write one cache line
            const long t = omp_get_thread_num(), nt = omp_get_num_threads();
            lo = count * t / nt;
            hi = count * (t + 1) / nt;
#endif
            evaluate(blocks, dt, lo, hi, true);
        }
    } else {
        evaluate(blocks, dt, 0, count, keep_forces_);
    }
    // spread the kept forces and add up, in the candidates' order
    ContactTotals tot;
    for (auto& c : candidates_) {
        Block& hb = blocks[c.hit_block];
        Block& tb = blocks[c.target_block];
        for (const auto& p : c.forces) {
            spread(hb, c.hit_face, hb.hits[c.hit_face][p.point].xi, p.force);
            spread(tb, p.target_face, p.target_xi, -p.force);
        }
        tot.stored += c.totals.stored;
        tot.dissipated += c.totals.dissipated;
        tot.active += c.totals.active;
        if (c.totals.worst_depth > tot.worst_depth) {
            tot.worst_depth = c.totals.worst_depth;
            tot.worst_hit = c.totals.worst_hit;
            tot.worst_target = c.totals.worst_target;
        }
    }
    return tot;
}

void ContactSet::evaluate(std::vector<Block>& blocks, double dt, long begin, long end, bool keep_forces) {
    // the geometry of the (hitting, target) pair of the candidates at hand
    int cached_h = -1, cached_t = -1;
    TargetSides sides;
    std::array<int, 6> best_side{};   // per target side: the hitting block's side most opposed to it
    std::array<char, 6> target_ok{};  // per target side: it is the target for that side
    double flush_tol = 0.0, closer_tol = 0.0;
    std::array<ParallelogramFrame, 6> frames;   // rigid parallelogram target sides: closed-form projection
    for (long ci = begin; ci < end; ++ci) {
        Candidate& c = candidates_[size_t(ci)];
        c.forces.clear();
        c.totals = ContactTotals{};
        ContactTotals& tot = c.totals;
        Block& hb = blocks[c.hit_block];
        Block& tb = blocks[c.target_block];
        if (c.hit_block != cached_h || c.target_block != cached_t) {
            cached_h = c.hit_block;
            cached_t = c.target_block;
            sides = sides_of(tb);
            TargetSides hsides = sides_of(hb);
            for (int s = 0; s < 6; ++s) {
                double best = 0.0;
                best_side[s] = -1;
                for (int f = 0; f < 6; ++f) {
                    double d = hsides.normal[f].dot(sides.normal[s]);
                    if (d < best) best = d, best_side[s] = f;
                }
                target_ok[s] = best_side[s] >= 0 && is_target(blocks, c.hit_block, best_side[s], c.target_block, s);
            }
            // a hitting point up to 1e-4 of the edge outside a side plane still counts as over
            // the target side: flush edges (stacked blocks) stay in contact as they bulge
            flush_tol = 1e-4 * tb.min_edge;
            closer_tol = 0.25 * tb.min_edge;
            for (int s = 0; s < 6; ++s)
                frames[s] = tb.mesh.side_grid[s].size() == 1 ? ParallelogramFrame::of(tb.side_quad(s)) : ParallelogramFrame{};
        }
        const int hit_side = hb.mesh.face_side[c.hit_face];
        // a face whose side is the hitting side of no target side cannot act: clear its anchors
        bool acts = false;
        for (int s = 0; s < 6; ++s) acts |= best_side[s] == hit_side && target_ok[s];
        if (!acts) {
            for (auto& a : c.anchors) a.side = -1;
            continue;
        }
        const Quad hq = hb.face_quad(c.hit_face);
        const auto& pts = hb.hits[c.hit_face];
        // damping coefficients per unit tributary area, N·s/m³
        double cn_area = 0.0, ct_area = 0.0;
        if (law_.damping_rule == ContactDampingRule::time) {
            cn_area = law_.damping * law_.kn;
            ct_area = law_.damping * law_.ks;
        } else if (law_.damping_rule == ContactDampingRule::ratio) {
            double m = reduced_mass(hb, tb), area = hb.side_area[hit_side];
            cn_area = 2.0 * law_.damping * std::sqrt(law_.kn * m / area);
            ct_area = 2.0 * law_.damping * std::sqrt(law_.ks * m / area);
        }
        for (size_t k = 0; k < pts.size(); ++k) {
            Anchor& anchor = c.anchors[k];
            const Vec3 xp = quad_point(hq, pts[k].xi);
            // the point acts on the allowed target side it lies deepest behind, if it is inside
            // the target block (behind every side plane, flush within rounding) and no other
            // side is clearly closer (it would be entering through that side instead)
            double dist[6];
            int side = -1;
            for (int s = 0; s < 6; ++s) {
                dist[s] = sides.normal[s].dot(xp - sides.centre[s]);
                if (best_side[s] == hit_side && target_ok[s] && (side < 0 || dist[s] > dist[side])) side = s;
            }
            bool inside = side >= 0 && dist[side] < 0.0;
            for (int s = 0; inside && s < 6; ++s)
                if (s != side && (dist[s] > flush_tol || dist[s] > dist[side] + closer_tol)) inside = false;
            if (!inside) {
                anchor.side = -1;
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
                anchor.side = -1;
                continue;
            }
            const double depth_ratio = depth / std::min(hb.min_edge, tb.min_edge);
            if (depth_ratio > tot.worst_depth) tot.worst_depth = depth_ratio, tot.worst_hit = c.hit_block, tot.worst_target = c.target_block;
            const double a = pts[k].area;
            // relative velocity of the hitting point against the target material point
            Vec3 vh = Vec3::Zero(), vt = Vec3::Zero();
            auto wh = quad_weights(pts[k].xi), wt = quad_weights(pr.xi);
            for (int i = 0; i < 4; ++i) {
                vh += wh[i] * hb.v[hb.mesh.faces[c.hit_face][i]];
                vt += wt[i] * tb.v[tb.mesh.faces[face][i]];
            }
            const Vec3 vrel = vh - vt;
            const double closing = -vrel.dot(n);
            // normal: penalty spring plus dashpot, never pulling
            const double fn_el = law_.kn * a * depth;
            double fn = std::max(0.0, fn_el + cn_area * a * closing);
            tot.dissipated += (fn - fn_el) * closing * dt;
            tot.stored += 0.5 * fn_el * depth;
            // shear: elastic from the stick anchor, capped at μ·Fn
            Vec3 fs = Vec3::Zero();
            if (law_.ks > 0.0 && fn > 0.0) {
                if (anchor.side != side) anchor = Anchor{side, face, pr.xi};
                const Vec3 x0_old = frame.valid ? frame.point(anchor.xi0) : quad_point(tb.face_quad(anchor.face), anchor.xi0);
                Vec3 u = pr.point - x0_old;
                u -= u.dot(n) * n;
                Vec3 vt_rel = vrel - vrel.dot(n) * n;
                const double ks_a = law_.ks * a;
                Vec3 f_el = -ks_a * u;
                const double cap = law_.friction * fn;
                if (f_el.norm() > cap) {
                    // slip: the spring is capped at μ·Fn and its anchor follows; no shear dashpot
                    fs = cap * f_el / f_el.norm();
                    Projection moved = frame.valid ? frame.project(pr.point + fs / ks_a) : project(tq, pr.point + fs / ks_a, pr.xi);
                    anchor.face = face;
                    anchor.xi0 = moved.xi;
                    // friction work: the force at the cap times the distance the anchor slipped
                    tot.dissipated += fs.norm() * (moved.point - x0_old).norm();
                    tot.stored += 0.5 * fs.squaredNorm() / ks_a;
                } else {
                    // stick: spring plus shear dashpot, the dashpot trimmed so the sum stays ≤ μ·Fn
                    fs = f_el - ct_area * a * vt_rel;
                    if (fs.norm() > cap) fs *= cap / fs.norm();
                    tot.stored += 0.5 * u.squaredNorm() * ks_a;
                    tot.dissipated -= (fs - f_el).dot(vt_rel) * dt;
                }
            } else {
                anchor.side = -1;
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
