// The overlap scheme (contact.scheme = "overlap"): the penalty integrated over the overlap of a
// hitting face with the target faces, on n×n sub-contacts per hitting face.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "contact.hpp"
#include "contact_overlap.hpp"
#include "contact_overlap_beyond.hpp"
#include "contact_overlap_edge.hpp"
#include "contact_reach.hpp"
#include "contact_twist.hpp"

namespace cairn::dem {

namespace {

constexpr int kMaxSubdivision = 16;   // the scene reader's bound on contact.subdivision
constexpr int kMaxConstraints = kMaxSideConstraints;
constexpr int kMaxBlend = 2;   // other sides in the facing rule's band blended at once (more: the nearer rule)

// the constraints of a target side under one choice of the facing rule for each other side in its
// band (contact_reach.hpp), and that choice's weight in the blend
struct SideRule {
    std::array<Affine, kMaxConstraints> cons;
    std::array<ReachCap, kMaxSideConstraints> caps;
    int side_count = 0, count = 0;
    bool capped = false, live = false;
    double weight = 1.0;
    int not_faced = 0;   // bit i: band side i taken as not faced
};

}  // namespace

void ContactSet::evaluate_overlap(std::vector<Block>& blocks, double dt, long begin, long end, bool keep_forces) {
    PairGeometry g;
    g.ties = &ties_;
    const int n = std::clamp(law_.subdivision, 1, kMaxSubdivision);
    std::array<Vec3, (kMaxSubdivision + 1) * (kMaxSubdivision + 1)> grid;   // sub-cell corners
    std::array<SideRule, 1 << kMaxBlend> rules;
    // per cell, each rule's clipped pieces and their integrals (laid out once: every cell writes
    // what it reads)
    std::array<std::array<ClipPolygon, 4>, 1 << kMaxBlend> polys;
    std::array<std::array<OverlapIntegrals, 4>, 1 << kMaxBlend> part;
    std::array<OverlapIntegrals, 1 << kMaxBlend> whole_in;
    // a rigid face's cells share their corners: each rule's constraints tested once at each grid
    // corner (bit q: inside, resp. outside, constraint q), as clip() tests them
    using CornerMasks = std::array<uint32_t, (kMaxSubdivision + 1) * (kMaxSubdivision + 1)>;
    std::array<CornerMasks, 1 << kMaxBlend> corner_in, corner_out;
    static_assert(kMaxConstraints <= 32, "a constraint per bit");
    for (long ci = begin; ci < end; ++ci) {
        Candidate& c = candidates_[size_t(ci)];
        ContactTotals& tot = c.totals;
        Block& hb = blocks[c.hit_block];
        Block& tb = blocks[c.target_block];
        std::vector<SubForce>* keep = keep_forces ? &c.sub_forces : nullptr;   // forces kept, or spread at once
        for (auto& a : c.subs) a.seen = false;
        size_t hint = 0;   // where the next cell's anchor is looked for first
        g.update(blocks, frames_, c.hit_block, c.target_block);
        const int hit_side = hb.mesh.face_side[c.hit_face];
        const std::array<char, 6>& faces = g.faces(hit_side);
        if (faces[0] || faces[1] || faces[2] || faces[3] || faces[4] || faces[5]) {
            const Quad hq = hb.face_quad(c.hit_face);
            Aabb hbox;
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i) grid[j * (n + 1) + i] = quad_point(hq, Vec2(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n));
            const auto [cn_area, ct_area] = dashpot_per_area(law_, hb, tb, hit_side);
            const TwistLaw twist_law{law_.ks, law_.friction, ct_area, slip_};
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
                // the facing rule of each other side o: faced or not, and inside its band both,
                // weighted by w(n_h·n_o) (contact_reach.hpp), each choice one rule for the cells
                const Vec3& nh = frames_[size_t(c.hit_block)].normal[size_t(hit_side)];
                std::array<signed char, 6> facing_of;
                std::array<int, kMaxBlend> band{};
                std::array<double, kMaxBlend> band_w{}, band_slope{};
                int nb = 0;
                for (int o = 0; o < 6; ++o) {
                    facing_of[size_t(o)] = -1;
                    if (o == s) continue;
                    const double co = nh.dot(g.normal[size_t(o)]);
                    const double w = not_facing_weight(co);
                    if (w > 0.0 && w < 1.0 && nb < kMaxBlend) {
                        band[size_t(nb)] = o;
                        band_w[size_t(nb)] = w;
                        band_slope[size_t(nb++)] = not_facing_slope(co);
                    }
                    else facing_of[size_t(o)] = w < 0.5 ? 1 : 0;
                }
                const int nrules = 1 << nb;
                bool any_live = false;
                for (int a = 0; a < nrules; ++a) {
                    SideRule& r = rules[size_t(a)];
                    r.weight = 1.0;
                    r.not_faced = a;
                    std::array<signed char, 6> f = facing_of;
                    for (int i = 0; i < nb; ++i) {
                        const bool not_faced = (a >> i) & 1;
                        f[size_t(band[size_t(i)])] = not_faced ? 0 : 1;
                        r.weight *= not_faced ? band_w[size_t(i)] : 1.0 - band_w[size_t(i)];
                    }
                    r.side_count = side_constraints(g, s, nh, false, r.cons, &hq, &r.caps, 0.0, &f);
                    // a capped cut keeps the region beyond it (contact_overlap_beyond.hpp): one that
                    // misses the face leaves it to that region
                    r.capped = false;
                    for (int k = 0; k < r.side_count; ++k) r.capped = r.capped || r.caps[size_t(k)].corner >= 0;
                    // (an uncapped rule on one rigid cell is left to clip(), which empties the cell at
                    // the first constraint its corners all miss: the same answer, and most faces touch)
                    bool missed = false;
                    const bool one_cell = n == 1 && !hb.deformable && !r.capped;
                    for (int k = 0; k < r.side_count && !missed && !one_cell; ++k)
                        if (!r.capped || r.caps[size_t(k)].corner < 0) missed = missed_by(r.cons.data() + k, r.cons.data() + k + 1);
                    r.live = !missed;
                    any_live = any_live || r.live;
                }
                if (!any_live) continue;
                // dU/dw of each band side (J): the blend's energy changes with w, so its force has
                // a couple about n_h × n_o (applied after the side's cells)
                std::array<double, kMaxBlend> dU_dw{};
                int touched_face = -1;   // a target face of the side that took force (for the couple's weights)
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
                    std::array<Affine, 5> face_cons;
                    int nf = 0;
                    face_cons[size_t(nf++)] = Affine{-nt, nt.dot(ct)};   // behind the face: d ≥ 0
                    // over the face: inside each edge; a face that is the whole side within the
                    // flush tolerance, as the other sides' planes (a face flush with the edge of
                    // an equal one is bounded by its own edge, which moves with it, and not by the
                    // target's, whose edge force would come and go as rounding moves one past
                    // the other: the arches' joints)
                    // (on a box those planes are the edges' own: the side's constraints hold them)
                    const double edge_tol = whole ? g.flush_tol : 0.0;
                    for (int i = 0; i < 4 && !(whole && tb.box); ++i) {
                        const Vec3 a = nt.cross(flat[(i + 1) % 4] - flat[i]).normalized();
                        face_cons[size_t(nf++)] = Affine{a, -a.dot(flat[i]) + edge_tol};
                    }
                    if (missed_by(face_cons.data(), face_cons.data() + nf)) continue;
                    const bool split = hb.deformable != nullptr;
                    // one cell is its face: clip() tests its corners as the masks would
                    const bool masks = !split && n > 1;
                    for (int a = 0; a < nrules; ++a) {
                        SideRule& r = rules[size_t(a)];
                        r.count = r.side_count;
                        for (int k = 0; k < nf; ++k) r.cons[size_t(r.count++)] = face_cons[size_t(k)];
                        if (!masks || !r.live) continue;
                        uint32_t* in = corner_in[size_t(a)].data();
                        uint32_t* out = corner_out[size_t(a)].data();
                        const int corners = (n + 1) * (n + 1);
                        std::fill(in, in + corners, 0u);
                        std::fill(out, out + corners, 0u);
                        for (int q = 0; q < r.count; ++q) {
                            const Affine& k = r.cons[size_t(q)];
                            for (int i = 0; i < corners; ++i) {
                                const double val = k(grid[size_t(i)]);   // as clip() computes it
                                in[i] |= uint32_t(val >= 0.0) << q;
                                out[i] |= uint32_t(val < 0.0) << q;
                            }
                        }
                    }
                    for (int v = 0; v < n; ++v)
                        for (int u = 0; u < n; ++u) {
                            // the sub-cell's corners (grid indices): a rigid block's cell is planar
                            // and clipped whole; a deformable block's element face may be warped,
                            // so its cell is taken as 4 planar triangles, each of two neighbouring
                            // corners and the cell's centre on the face (a warp of the face moves
                            // neither the centre nor, to first order, ∫d dA, as on the bilinear
                            // face). Over each d is affine and ∫kn·d·λ_i dA = λ_i(x̄)·kn∫d dA: the
                            // normal force at each triangle's pressure centre, spread by its
                            // barycentric weights, is the gradient of the energy it books
                            const std::array<int, 4> corner = {v * (n + 1) + u, v * (n + 1) + u + 1, (v + 1) * (n + 1) + u + 1,
                                                               (v + 1) * (n + 1) + u};
                            const int parts = split ? 4 : 1;
                            // natural coordinates on the hitting face of the triangles' corners
                            auto corner_xi = [&](int i) {
                                return Vec2(-1.0 + 2.0 * (corner[size_t(i)] % (n + 1)) / n, -1.0 + 2.0 * (corner[size_t(i)] / (n + 1)) / n);
                            };
                            const Vec2 centre_xi = Vec2(-1.0 + (2.0 * u + 1.0) / n, -1.0 + (2.0 * v + 1.0) / n);
                            const Vec3 centre_p = split ? quad_point(hq, centre_xi) : Vec3::Zero();
                            // triangle k's corners in natural coordinates of the hitting face
                            auto triangle_xi = [&](int k) {
                                return std::array<Vec2, 3>{corner_xi(k), corner_xi((k + 1) % 4), centre_xi};
                            };
                            // piece k of the cell, unclipped, into poly (its corners only): the cell
                            // itself, or its triangle k
                            auto piece = [&](int k, ClipPolygon& poly) {
                                if (split) {
                                    poly.n = 3;
                                    poly.p[0] = grid[size_t(corner[size_t(k)])];
                                    poly.p[1] = grid[size_t(corner[size_t((k + 1) % 4)])];
                                    poly.p[2] = centre_p;
                                } else {
                                    poly.n = 4;
                                    for (int i = 0; i < 4; ++i) poly.p[size_t(i)] = grid[size_t(corner[size_t(i)])];
                                }
                                for (int i = 0; i < poly.n; ++i) poly.by[size_t(i)] = 0;   // edges as given
                            };
                            // each rule's energy in this cell (J, unweighted), for dU/dw
                            std::array<double, 1 << kMaxBlend> energy{};
                            for (int a = 0; a < nrules; ++a) {
                                const SideRule& r = rules[size_t(a)];
                                if (!r.live || !r.capped) continue;
                                std::array<ClipPolygon, 4> pieces;
                                BeyondCell bc;
                                bc.parts = parts;
                                bc.pieces = &pieces;
                                for (int k = 0; k < parts; ++k) {
                                    piece(k, pieces[size_t(k)]);
                                    if (split) bc.piece_xi[size_t(k)] = triangle_xi(k);
                                }
                                bc.cons = r.cons.data();
                                bc.side_count = r.side_count;
                                bc.count = r.count;
                                bc.caps = r.caps.data();
                                bc.g = &g;
                                bc.c = ct;
                                bc.n = nt;
                                bc.hit_face = &hq;
                                bc.target_face = &tq;
                                bc.kn = law_.kn;
                                bc.scale = r.weight;
                                energy[size_t(a)] = apply_beyond(bc, hb, c.hit_face, tb, tf, keep);
                                tot.stored += r.weight * energy[size_t(a)];
                            }
                            // each rule's clipped pieces and integrals; the cell's are their blend
                            OverlapIntegrals in;
                            bool any = false;
                            for (int a = 0; a < nrules; ++a) {
                                const SideRule& r = rules[size_t(a)];
                                OverlapIntegrals& ra = whole_in[size_t(a)];
                                ra = OverlapIntegrals{};
                                for (int k = 0; k < parts; ++k) {
                                    ClipPolygon& poly = polys[size_t(a)][size_t(k)];
                                    piece(k, poly);
                                    if (!r.live) poly.n = 0;
                                    // a rigid cell is clipped from the first constraint not met by
                                    // all its corners (those before leave it as it is), and is
                                    // empty if all its corners miss that one: clip()'s very result
                                    int first = 0;
                                    if (masks && poly.n > 0) {
                                        uint32_t in = ~0u, out = ~0u;
                                        for (int i : corner) in &= corner_in[size_t(a)][size_t(i)], out &= corner_out[size_t(a)][size_t(i)];
                                        while (first < r.count && ((in >> first) & 1u)) ++first;
                                        if (first < r.count && ((out >> first) & 1u)) poly.n = 0;
                                    }
                                    for (int q = first; q < r.count && poly.n >= 3; ++q) clip(poly, r.cons[size_t(q)], q);
                                    if (poly.n < 3) {
                                        poly.n = 0;
                                        continue;
                                    }
                                    any = true;
                                    part[size_t(a)][size_t(k)] = integrate_depth(poly, ct, nt);
                                    const OverlapIntegrals& pk = part[size_t(a)][size_t(k)];
                                    if (!split) {
                                        ra = pk;
                                        continue;
                                    }
                                    ra.area += pk.area;
                                    ra.d1 += pk.d1;
                                    ra.d2 += pk.d2;
                                    ra.moment += pk.moment;
                                    ra.first += pk.first;
                                }
                                energy[size_t(a)] += 0.5 * law_.kn * ra.d2;
                                if (nrules == 1) {
                                    in = ra;
                                    continue;
                                }
                                in.area += r.weight * ra.area;
                                in.d1 += r.weight * ra.d1;
                                in.d2 += r.weight * ra.d2;
                                in.moment += r.weight * ra.moment;
                                in.first += r.weight * ra.first;
                                in.tilt += r.weight * ra.tilt;
                            }
                            // dU/dw_i = Σ over rules of dweight/dw_i times the rule's energy
                            for (int a = 0; a < nrules && nb > 0; ++a) {
                                const SideRule& r = rules[size_t(a)];
                                for (int i = 0; i < nb; ++i) {
                                    const bool not_faced = (r.not_faced >> i) & 1;
                                    const double wi = band_w[size_t(i)];
                                    dU_dw[size_t(i)] += (not_faced ? r.weight / wi : -r.weight / (1.0 - wi)) * energy[size_t(a)];
                                }
                            }
                            if (!any) continue;
                            if (!(in.d1 > 0.0) || !(in.area > 0.0)) continue;
                            touched_face = tf;
                            // how deep a point is in the target: its distance to the nearest
                            // side (a sliver of a face crossing a side nearly square to it may lie
                            // up to the closer tolerance behind that side, yet just under the one
                            // it entered through). Its depth behind the face bounds that: below
                            // the depth that stops the run the bound is all the check needs
                            const double smaller = std::min(hb.min_edge, tb.min_edge);
                            double dmax = 0.0;
                            for (int ak = 0; ak < nrules * parts; ++ak) {   // each rule's pieces
                                const ClipPolygon& poly = polys[size_t(ak / parts)][size_t(ak % parts)];
                                for (int i = 0; i < poly.n; ++i) dmax = std::max(dmax, nt.dot(ct - poly.p[size_t(i)]));
                            }
                            if (dmax > kSankDepth * smaller) {
                                dmax = 0.0;
                                for (int ak = 0; ak < nrules * parts; ++ak) {
                                    const ClipPolygon& poly = polys[size_t(ak / parts)][size_t(ak % parts)];
                                    for (int i = 0; i < poly.n; ++i) {
                                        const Vec3& p = poly.p[size_t(i)];
                                        double d = nt.dot(ct - p);
                                        for (int o = 0; o < 6; ++o)
                                            if (o != s) d = std::min(d, g.normal[o].dot(g.centre[o] - p));
                                        dmax = std::max(dmax, d);
                                    }
                                }
                            }
                            const double depth_ratio = dmax / smaller;
                            if (depth_ratio > tot.worst_depth) tot.worst_depth = depth_ratio, tot.worst_hit = c.hit_block, tot.worst_target = c.target_block;
                            // the sub-contact's anchor, found or new
                            const int cell = v * n + u;
                            // (the cells come in the order of the last evaluation, so the one
                            // after the last found is tried first: a scan of the whole list per
                            // cell read n⁴ anchors a face, 5 % of a wall's step at n = 4)
                            SubAnchor* anchor = nullptr;
                            if (hint < c.subs.size() && c.subs[hint].cell == cell && c.subs[hint].target_face == tf)
                                anchor = &c.subs[hint];
                            else
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
                            hint = size_t(anchor - c.subs.data()) + 1;
                            // the shear spring is a uniform traction ks·u over the clipped area: it
                            // acts at the area's centroid xc on the target plane, on both blocks,
                            // and its offset grows with the relative velocity there (the area's
                            // mean). At the pressure centre instead, a point that runs across the
                            // face as a joint hinges, one sub-contact per face made energy, first
                            // order in dt (structures/arch_thick, deformable: 0.96 / 0.51 / 0.23 %
                            // of the motion energy at dt_safety 0.1 / 0.05 / 0.025; 0.021 % now)
                            const Vec3 xc = in.first / in.area;
                            const NodeWeights wh = node_weights(hb, c.hit_face, xc), wt = node_weights(tb, tf, xc);
                            // the normal force acts at the pressure centre xs on the target plane,
                            // moved by the tilt couple on a rigid hitting face
                            // (OverlapIntegrals::action_point; see the edge forces below), on both
                            // blocks (a collinear pair); on a deformable block by the weights that
                            // make it the gradient of ½kn∫d² dA (rigid: any weights reproduce the
                            // force and its moment)
                            const Vec3 xs = split ? in.pressure_centre() : in.action_point();
                            NodeWeights wh_n, wt_n;
                            if (!split) wh_n = node_weights(hb, c.hit_face, xs);
                            else {
                                // each triangle's pressure centre, by its barycentric weights on
                                // its (projected) corners, each a point of the face's bilinear map
                                // (inside the facing rule's band, each rule's triangles by its weight)
                                std::array<double, 4> w{};
                                constexpr double eta = 1e-12;   // as in pressure_centre()
                                const double total = in.d1 + eta * in.area;
                                for (int k = 0; k < 4; ++k) {
                                    const auto txi = triangle_xi(k);
                                    std::array<Vec3, 3> x;
                                    for (int i = 0; i < 3; ++i) {
                                        const Vec3 p = quad_point(hq, txi[size_t(i)]);
                                        x[size_t(i)] = p + nt.dot(ct - p) * nt;
                                    }
                                    for (int a = 0; a < nrules; ++a) {
                                        const OverlapIntegrals& pk = part[size_t(a)][size_t(k)];
                                        if (polys[size_t(a)][size_t(k)].n == 0 || !(pk.area > 0.0)) continue;   // nothing of it in contact
                                        const double weight = nrules == 1 ? 1.0 : rules[size_t(a)].weight;
                                        add_triangle_weights(x, txi, pk.pressure_centre(), nt, weight * (pk.d1 + eta * pk.area) / total, w);
                                    }
                                }
                                wh_n = face_node_weights(hb, c.hit_face, w);
                            }
                            wt_n = tb.deformable ? plane_weights(tq, tb.mesh.faces[tf], ct, nt, xs) : node_weights(tb, tf, xs);
                            const Vec3 vrel = wh.velocity(hb) - wt.velocity(tb);
                            const double closing = -(wh_n.velocity(hb) - wt_n.velocity(tb)).dot(nt);
                            // normal: the exact integral of kn·d, plus the dashpot, never pulling
                            const double fn_el = law_.kn * in.d1;
                            const double fn = std::max(0.0, fn_el + cn_area * in.area * closing);
                            // the dashpot's work as the leapfrog step does it: each end's force
                            // times the step's closing where that force acted (the start's at
                            // the last evaluation's point and normal: the pressure centre runs
                            // across a face that lifts or lands)
                            const double fd = fn - fn_el;
                            Vec3 fds = Vec3::Zero();
                            const double closing_before =
                                fresh ? 0.0 : -(anchor->hit_at.velocity(hb) - anchor->target_at.velocity(tb)).dot(anchor->normal);
                            tot.dissipated += 0.5 * (anchor->fd * closing_before + fd * closing) * dt;
                            const double stored_before = fresh ? 0.0 : anchor->stored;
                            const double spring_before = fresh ? 0.0 : anchor->spring;
                            const bool edged_before = !fresh && anchor->edged;
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
                                    c.events.push_back({c.hit_block, wh_n, (f_end - fn_el) * nt});
                                    c.events.push_back({c.target_block, wt_n, (fn_el - f_end) * nt});
                                }
                            }
                            anchor->fel = fn > 0.0 ? fn_el : 0.0;
                            anchor->spring = fn_el;
                            anchor->stored = 0.5 * law_.kn * in.d2;
                            anchor->normal = nt;
                            anchor->hit_at = wh_n;
                            anchor->target_at = wt_n;
                            Vec3 fs = Vec3::Zero();
                            if (law_.ks > 0.0 && fn > 0.0) {
                                // the shear offset grows with the relative tangential motion at the
                                // pressure centre over the step (the half-step velocity is the one
                                // the positions drifted with); laid at zero on first touch
                                const bool lay = fresh || anchor->energy < 0.0;
                                if (lay) anchor->u.setZero();
                                const Vec3 vt_new = vrel - vrel.dot(nt) * nt;
                                // the step's relative motion where the last force acted and where this
                                // one acts (the clipped area's centroid runs across a face that lands,
                                // lifts or turns): the offset grows with their mean
                                const Vec3 v_old =
                                    lay ? vrel : Vec3(anchor->shear_hit.velocity(hb) - anchor->shear_target.velocity(tb));
                                const Vec3 vt_old = v_old - v_old.dot(nt) * nt;
                                const Vec3 vt_rel = 0.5 * (vt_old + vt_new);
                                Vec3 u_t = anchor->u - anchor->u.dot(nt) * nt + vt_rel * dt;
                                // the spring's stiffness ks·A follows the contact area; the offset
                                // is scaled so that a change of area neither makes nor takes spring
                                // energy (½ks·A·u² kept: u scaled by √(A_old/A)), and its growth over
                                // the step by the step's mean √A (s = √A·u grows by √A·v·dt: with
                                // √A_old alone the step's work missed the spring's energy by
                                // ½ks·(√A − √A_old)·√A·u·v·dt, first order where areas change fast)
                                if (!lay && anchor->area > 0.0) {
                                    const double scale = std::sqrt(anchor->area / in.area);
                                    const Vec3 u_old = (anchor->u - anchor->u.dot(nt) * nt) * scale;
                                    u_t = u_old + (0.5 * (1.0 + scale)) * vt_rel * dt;
                                }
                                anchor->area = in.area;
                                const double ks_a = law_.ks * in.area;
                                const Vec3 f_el = -ks_a * u_t;
                                const double cap = slip_ ? law_.friction * fn : std::numeric_limits<double>::max();
                                if (f_el.norm() > cap) {
                                    // slip: the spring is capped at μ·Fn, the offset shrinks to match
                                    const double energy_before = lay ? 0.0 : anchor->energy;
                                    const Vec3 fs_before = lay ? Vec3::Zero() : anchor->fs;
                                    fs = cap * f_el / f_el.norm();
                                    const Vec3 u_new = -fs / ks_a;
                                    anchor->u = u_new;
                                    anchor->energy = 0.5 * fs.squaredNorm() / ks_a;
                                    // friction work over the step: what the shear forces took from
                                    // the blocks (the leapfrog step's trapezoid, each end's force
                                    // times the motion where it acted) less what the spring kept
                                    const double taken = -0.5 * dt * (fs_before.dot(v_old) + fs.dot(vt_new));
                                    tot.dissipated += taken - (anchor->energy - energy_before);
                                } else {
                                    // stick: spring plus shear dashpot, trimmed so the sum stays ≤ μ·Fn
                                    fs = f_el - ct_area * in.area * vt_new;
                                    if (fs.norm() > cap) fs *= cap / fs.norm();
                                    anchor->u = u_t;
                                    anchor->energy = 0.5 * ks_a * u_t.squaredNorm();
                                    fds = fs - f_el;
                                    tot.dissipated -= 0.5 * (anchor->fds.dot(v_old) + fds.dot(vt_new)) * dt;
                                }
                                tot.stored += anchor->energy;
                                // its torsion spring (a disc of its area) resists the spin about n
                                TwistInput ti;
                                ti.area = in.area;
                                ti.normal_force = fn;
                                ti.shear_force = fs.norm();
                                ti.centroid = xc;
                                ti.normal = nt;
                                ti.edge = hq[1] - hq[0];
                                ti.lay = lay;
                                update_twist(anchor->twist, ti, twist_law, hb, c.hit_face, tb, tf, dt, tot);
                            } else {
                                // no normal force: the anchor is given up (re-laid at the next touch)
                                tot.dissipated += std::max(0.0, anchor->energy);
                                anchor->energy = -1.0;
                                anchor->area = 0.0;
                                release_twist(anchor->twist, hb, tb, dt, tot);
                            }
                            anchor->fds = fds;
                            anchor->fs = fs;
                            anchor->shear_hit = wh;
                            anchor->shear_target = wt;
                            const Vec3 force = fn * nt + fs;
                            SubForce::put(keep, wh, wt, force, nt, wh_n, wt_n, hb, tb);
                            add_twist_forces(anchor->twist, nt, keep, hb, tb);
                            // where the polygon ends on a constraint fixed to the target (a target
                            // face's edge, another side's plane) with depth, U changes as the
                            // face moves over it: the boundary term of the gradient, on both blocks
                            // at the edge's hitting points (the cell's own edges move with it, and
                            // d = 0 on the depth cut). On a deformable hitting face, per triangle
                            // (d is affine over each), spread on the face's nodes by the point's
                            // barycentric weights in its triangle: without it a brick landing across
                            // the edges of another lost 7.4 % of its motion energy unbooked
                            anchor->edged = false;
                            for (int ak = 0; ak < nrules * parts; ++ak) {   // each rule's pieces
                                const int a = ak / parts, k = ak % parts;
                                const SideRule& r = rules[size_t(a)];
                                const double weight = nrules == 1 ? 1.0 : r.weight;
                                const auto& caps = r.caps;
                                const int side_count = r.side_count;
                                const ClipPolygon& poly = polys[size_t(a)][size_t(k)];
                                const Vec3 slope = split ? part[size_t(a)][size_t(k)].slope : whole_in[size_t(a)].slope;
                                for (int i = 0; i < poly.n; ++i) {
                                    const int cut = int(poly.by[size_t(i)]) - 1;
                                    if (cut < 0 || cut == side_count) continue;
                                    if (r.capped && cut < side_count && caps[size_t(cut)].corner >= 0) continue;   // joins the region beyond
                                    EdgeForce e = edge_force(poly, i, ct, nt, r.cons[size_t(cut)], slope, law_.kn);
                                    e.force *= weight;
                                    e.offset_gradient *= weight;
                                    if (e.force.isZero(0.0)) continue;
                                    anchor->edged = true;
                                    NodeWeights eh;
                                    if (!split) eh = node_weights(hb, c.hit_face, e.point);
                                    else {
                                        const Vec3& x0 = grid[size_t(corner[size_t(k)])];
                                        const Vec3& x1 = grid[size_t(corner[size_t((k + 1) % 4)])];
                                        const Vec3 tn = (x1 - x0).cross(centre_p - x0).normalized();
                                        std::array<double, 4> w{};
                                        add_triangle_weights({x0, x1, centre_p}, triangle_xi(k), e.point, tn, 1.0, w);
                                        eh = face_node_weights(hb, c.hit_face, w);
                                    }
                                    // on the target at the same point (a collinear pair): it
                                    // pushes along the plane, and a deformable target's plane
                                    // weights would put it at the point's projection, a couple
                                    // that made energy as two columns pressed side by side
                                    const NodeWeights et = node_weights(tb, tf, e.point);
                                    // a push off the edge: all of it normal in the output
                                    SubForce::put(keep, eh, et, e.force, e.force.normalized(), eh, et, hb, tb);
                                    // a closer constraint capped at the face's reach behind o moves
                                    // with the face's deepest corner p along −n_o: U's gradient there
                                    // is dU/db·(−n_o), a pair at p (the reach is o's plane to p,
                                    // unchanged by a motion of both blocks)
                                    if (cut < side_count && caps[size_t(cut)].corner >= 0) {
                                        const Vec3& cp = hq[size_t(caps[size_t(cut)].corner)];
                                        const NodeWeights ch = node_weights(hb, c.hit_face, cp), ctw = node_weights(tb, tf, cp);
                                        const Vec3& no = g.normal[size_t(caps[size_t(cut)].side)];   // it pushes on o
                                        SubForce::put(keep, ch, ctw, e.offset_gradient * no, no, ch, ctw, hb, tb);
                                    }
                                }
                            }
                            // a face pulling away faster than its springs relax: the dashpot
                            // cancels the spring (the force is clipped at zero, nothing pushes), so
                            // its work is minus the spring's, the spring's exact energy change, not
                            // the trapezoid of its force: U = ½kn∫d² dA over a clipped region that
                            // shrinks is not quadratic in the motion (a wedge's goes as its depth
                            // cubed), and the trapezoid booked more than the spring gave back
                            // (docs/dem.md, Energy). Rigid faces away from the target's edges
                            // (their boundary forces share the work)
                            if (!fresh && !split && !anchor->edged && !edged_before && spring_before > 0.0 && fn == 0.0) {
                                const double trapezoid = 0.5 * (spring_before * closing_before + fn_el * closing) * dt;
                                tot.dissipated += trapezoid - (anchor->stored - stored_before);
                            }
                            ++tot.active;
                        }
                }
                // the blend's couple: U = Σ weight·U_rule changes with w_i(c), c = n_h·n_o, and
                // c turns with either block about n_h × n_o: −dU/dw·dw/dc·(n_h × n_o) on the
                // hitting block and its opposite on the target, as a pair of opposite forces at
                // the face's centre on both (the same points)
                for (int i = 0; i < nb && touched_face >= 0; ++i) {
                    const Vec3 tau = -dU_dw[size_t(i)] * band_slope[size_t(i)] * nh.cross(g.normal[size_t(band[size_t(i)])]);
                    if (!(tau.norm() > 0.0)) continue;
                    const ForcePair pair = couple_as_pair(tau, nh, hb.min_edge);
                    const Vec3 centre = 0.25 * (hq[0] + hq[1] + hq[2] + hq[3]);
                    for (const double side : {1.0, -1.0}) {
                        const Vec3 x = centre + side * pair.offset;
                        const NodeWeights xh = node_weights(hb, c.hit_face, x), xt = node_weights(tb, touched_face, x);
                        const Vec3 force = side * pair.force;
                        SubForce::put(keep, xh, xt, force, force.normalized(), xh, xt, hb, tb);
                    }
                }
            }
        }
        // anchors out of contact release their shear springs: that energy is dissipated
        size_t kept = 0;
        for (size_t i = 0; i < c.subs.size(); ++i) {
            const SubAnchor& a = c.subs[i];
            if (a.seen) {
                if (kept != i) c.subs[kept] = a;
                ++kept;
                continue;
            }
            tot.dissipated += std::max(0.0, a.energy);
            // its last shear force did work over the step too (the start's half kick)
            tot.dissipated -= 0.5 * dt * a.fs.dot(a.shear_hit.velocity(hb) - a.shear_target.velocity(tb));
            SubTwist twist = a.twist;
            release_twist(twist, hb, tb, dt, tot);
            if (a.fd == 0.0 && !(a.fel > 0.0)) continue;
            // it left in this step, its force clipped to zero at the last evaluation (the
            // dashpot cancelled the spring): nothing pushed, and the dashpot took the spring's
            // energy U0
            if (!(a.fel > 0.0) && a.spring > 0.0 && !a.edged) {
                tot.dissipated += a.stored;
                continue;
            }
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
