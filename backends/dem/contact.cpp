#include "contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "broad_phase.hpp"
#include "contact_reach.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace cairn::dem {

namespace {
constexpr size_t kParallelContactWork = 30000;   // hitting points: see ContactSet::apply
}  // namespace

void ContactSet::configure(const ContactLaw& law, double margin) {
    law_ = law;
    margin_ = margin;
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
    broad_.overlapping_pairs(boxes_, pairs_);
    // overlap scheme: faces that cannot reach the target before the next refresh are left out
    const bool prune = prune_ && law_.scheme == ContactScheme::overlap;
    if (prune) {
        frames_.resize(blocks.size());
        for (size_t i = 0; i < blocks.size(); ++i) frames_[i] = SideFrames::of(blocks[i]);
    }
    PairGeometry g;
    g.ties = &ties_;
    slots_.clear();
    widened_.assign(prune ? blocks.size() : 0, 0);
    for (auto [i, j] : pairs_) {
        if (blocks[i].fixed && blocks[j].fixed) continue;
        for (auto [h, t] : {std::pair<int, int>{i, j}, std::pair<int, int>{j, i}}) {
            for (int f = 0; f < int(blocks[h].mesh.faces.size()); ++f) {
                Aabb fb;
                for (int n : blocks[h].mesh.faces[f]) fb.add(blocks[h].x[n]);
                fb.inflate(0.5 * margin_);
                if (!fb.overlaps(boxes_[t])) continue;
                if (prune) {
                    const bool acts = may_act(blocks, frames_, h, f, t, margin_, g);
                    slots_.push_back({h, f, t, acts});
                    if (!acts) continue;
                }
                Candidate c;
                c.hit_block = h;
                c.hit_face = f;
                c.target_block = t;
                auto it = std::lower_bound(previous_.begin(), previous_.end(), c,
                                           [&](const Candidate& a, const Candidate& b) { return key(a) < key(b); });
                if (it != previous_.end() && key(*it) == key(c)) {
                    c.anchors = std::move(it->anchors);
                    c.forces = std::move(it->forces);   // keeps its capacity: no allocation in the step
                    c.subs = std::move(it->subs);
                    c.sub_forces = std::move(it->sub_forces);
                }
                if (law_.scheme == ContactScheme::paper) c.anchors.resize(blocks[h].hits[f].size());
                candidates_.push_back(std::move(c));
            }
        }
    }
}

void ContactSet::widen(const std::vector<char>& turned) {
    bool any = false;
    for (size_t i = 0; i < widened_.size() && i < turned.size(); ++i)
        if (turned[i] && !widened_[i]) widened_[i] = 1, any = true;
    if (!any) return;
    // the active slots are the candidates, in the same order
    spare_.clear();
    size_t k = 0;
    for (Slot& s : slots_) {
        if (s.active) {
            spare_.push_back(std::move(candidates_[k++]));
            continue;
        }
        if (!widened_[size_t(s.hit_block)] && !widened_[size_t(s.target_block)]) continue;
        s.active = true;
        Candidate c;
        c.hit_block = s.hit_block;
        c.hit_face = s.hit_face;
        c.target_block = s.target_block;
        spare_.push_back(std::move(c));
    }
    candidates_.swap(spare_);
}

ContactTotals ContactSet::apply(std::vector<Block>& blocks, double dt) {
    frames_.resize(blocks.size());
    for (size_t i = 0; i < blocks.size(); ++i) frames_[i] = SideFrames::of(blocks[i]);
    const long count = long(candidates_.size());
    // the step's contact work in hitting points; an overlap sub-contact (clipping and integration)
    // costs about 8 of them. Below kParallelContactWork a parallel region costs more than it saves
    // (libgomp's threads sleep between steps and the wake-up outweighs the split; measured on
    // generated walls, docs/dem.md): one thread then spreads the forces as it goes
    size_t work = 0;
    const size_t cells = size_t(law_.subdivision) * size_t(law_.subdivision);
    for (const auto& c : candidates_) work += law_.scheme == ContactScheme::paper ? c.anchors.size() : 8 * cells;
    if (work >= kParallelContactWork) {
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
    if (law_.scheme == ContactScheme::overlap) remember_ties(blocks);
    // spread the kept forces and add up, in the candidates' order
    ContactTotals tot;
    events_.clear();
    for (auto& c : candidates_) {
        events_.insert(events_.end(), c.events.begin(), c.events.end());
        Block& hb = blocks[c.hit_block];
        Block& tb = blocks[c.target_block];
        for (const auto& p : c.forces) {
            spread(hb, c.hit_face, hb.hits[c.hit_face][p.point].xi, p.force);
            spread(tb, p.target_face, p.target_xi, -p.force);
        }
        for (const auto& p : c.sub_forces) p.spread(hb, tb);
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

void ContactSet::remember_ties(const std::vector<Block>& blocks) {
    // the ties in the candidates' order; sorted again only when they changed (a wall at rest: never).
    // Only those near the rule's switch, or kept already, need keeping: away from it the rule gives
    // the role it gave at first touch, so the memory stays small (empty for a wall at rest)
    tie_scratch_.clear();
    for (const auto& c : candidates_) {
        const int hit_side = blocks[size_t(c.hit_block)].mesh.face_side[size_t(c.hit_face)];
        int last = -1;   // a face's sub-contacts mostly share their target side: each side once
        for (const auto& a : c.subs) {   // the sub-contacts in contact now
            const int target_side = blocks[size_t(c.target_block)].mesh.face_side[size_t(a.target_face)];
            if (target_side == last) continue;
            last = target_side;
            if (!tie_by_geometry(blocks, c.hit_block, hit_side, c.target_block, target_side)) continue;
            const Vec3& nh = frames_[size_t(c.hit_block)].normal[size_t(hit_side)];
            const Vec3& nt = frames_[size_t(c.target_block)].normal[size_t(target_side)];
            if (near_tie_switch(nh, nt) || ties_.role(c.hit_block, hit_side, c.target_block, target_side) != 0)
                tie_scratch_.push_back({c.hit_block, hit_side, c.target_block, target_side});
        }
    }
    if (tie_scratch_ == tie_order_) return;
    tie_order_.swap(tie_scratch_);
    ties_.kept = tie_order_;
    ties_.index(blocks.size());
}

void ContactSet::evaluate(std::vector<Block>& blocks, double dt, long begin, long end, bool keep_forces) {
    // this step's forces and totals start empty
    for (long ci = begin; ci < end; ++ci) {
        Candidate& c = candidates_[size_t(ci)];
        c.forces.clear();
        c.sub_forces.clear();
        c.events.clear();
        c.totals = ContactTotals{};
    }
    if (law_.scheme == ContactScheme::paper) evaluate_paper(blocks, dt, begin, end, keep_forces);
    else evaluate_overlap(blocks, dt, begin, end, keep_forces);
}

}  // namespace cairn::dem
