#include "time_step.hpp"

#include <algorithm>
#include <cmath>

#include "broad_phase.hpp"
#include "geometry/spring_bed.hpp"

namespace cairn::dem {

double side_contact_omega2(const Block& b, int side, const ContactLaw& law) {
    const Quad q = b.side_quad(side);
    const Vec3 n = quad_normal(q, Vec2::Zero());
    // the springs of a whole side: the paper's hitting points, or (overlap scheme) the exact
    // integral over the side, which 2×2 Gauss points give for the quadratic integrand
    std::vector<HitPoint> hits;
    if (law.scheme == ContactScheme::paper) {
        hits = hit_grid(q, law.grid_spacing);
    } else {
        const double gp = 1.0 / std::sqrt(3.0), area = quad_area(q);
        for (double u : {-gp, gp})
            for (double v : {-gp, gp}) hits.push_back({Vec2(u, v), 0.25 * area});
    }
    std::vector<BedSpring> springs;
    springs.reserve(hits.size());
    for (const auto& p : hits) springs.push_back({quad_point(q, p.xi), p.area});
    const Mat3 rot = b.body.q.toRotationMatrix();
    const Mat3 inertia = rot * b.body.inertia_body * rot.transpose();
    return spring_bed_omega2(springs, n, law.kn, law.ks, b.body.x, b.body.mass, inertia);
}

double contact_critical_step(const std::vector<Block>& blocks, const ContactLaw& law, double reach) {
    // per free block: its stiffest side against a rigid base
    std::vector<double> w2_of(blocks.size(), 0.0);
    std::vector<double> free_w2;
    for (size_t i = 0; i < blocks.size(); ++i) {
        if (blocks[i].fixed) continue;
        for (int s = 0; s < 6; ++s) w2_of[i] = std::max(w2_of[i], side_contact_omega2(blocks[i], s, law));
        free_w2.push_back(w2_of[i]);
    }
    if (free_w2.empty()) return 0.0;
    double w2 = *std::max_element(free_w2.begin(), free_w2.end());   // a block alone on a base
    if (reach < 0.0) {
        std::sort(free_w2.rbegin(), free_w2.rend());
        if (free_w2.size() > 1) w2 = free_w2[0] + free_w2[1];
    } else {
        // the pairs of free blocks whose grown boxes overlap (the broad phase, O(N))
        std::vector<Aabb> boxes;
        boxes.reserve(blocks.size());
        for (const auto& b : blocks) {
            Aabb a = b.bounds();
            a.inflate(0.5 * reach);
            boxes.push_back(a);
        }
        std::vector<std::pair<int, int>> pairs;
        BroadPhase().overlapping_pairs(boxes, pairs);
        for (const auto& [i, j] : pairs)
            if (!blocks[i].fixed && !blocks[j].fixed) w2 = std::max(w2, w2_of[i] + w2_of[j]);
    }
    if (!(w2 > 0.0)) return 0.0;
    double w = std::sqrt(w2);
    double zeta = 0.0;
    if (law.damping_rule == ContactDampingRule::ratio) zeta = law.damping;
    if (law.damping_rule == ContactDampingRule::time) zeta = 0.5 * law.damping * w;
    return 2.0 / w * (std::sqrt(1.0 + zeta * zeta) - zeta);
}

double element_critical_step(const std::vector<Block>& blocks) {
    double dt = 0.0;
    for (const auto& b : blocks) {
        if (!b.deformable || b.fixed) continue;
        const double w = b.deformable->max_element_omega(), zeta = 0.5 * b.deformable->beta() * w;
        const double dt_b = 2.0 / w * (std::sqrt(1.0 + zeta * zeta) - zeta);
        dt = dt == 0.0 ? dt_b : std::min(dt, dt_b);
    }
    return dt;
}

}  // namespace cairn::dem
