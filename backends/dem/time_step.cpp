#include "time_step.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "broad_phase.hpp"

namespace cairn::dem {

double side_contact_omega2(const Block& b, int side, const ContactLaw& law) {
    using Mat6 = Eigen::Matrix<double, 6, 6>;
    using Vec6 = Eigen::Matrix<double, 6, 1>;
    const Quad q = b.side_quad(side);
    const Vec3 n = quad_normal(q, Vec2::Zero());
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    Mat6 k = Mat6::Zero();
    // the springs of a whole side: the paper's hitting points, or (overlap scheme) the exact
    // integral over the side, which 2×2 Gauss points give for the quadratic integrand
    std::vector<HitPoint> springs;
    if (law.scheme == ContactScheme::paper) {
        springs = hit_grid(q, law.grid_spacing);
    } else {
        const double gp = 1.0 / std::sqrt(3.0), area = quad_area(q);
        for (double u : {-gp, gp})
            for (double v : {-gp, gp}) springs.push_back({Vec2(u, v), 0.25 * area});
    }
    for (const auto& p : springs) {
        Vec3 r = quad_point(q, p.xi) - b.body.x;
        auto add = [&](const Vec3& d, double stiff) {
            Vec6 g;
            g << d, r.cross(d);
            k += stiff * p.area * g * g.transpose();
        };
        add(n, law.kn);
        add(t1, law.ks);
        add(t2, law.ks);
    }
    // M^{-1/2} K M^{-1/2} with M = diag(m, I_world)
    Mat3 rot = b.body.q.toRotationMatrix();
    Mat3 iw = rot * b.body.inertia_body * rot.transpose();
    Eigen::SelfAdjointEigenSolver<Mat3> ei(iw);
    Mat3 iw_inv_sqrt = ei.eigenvectors() * ei.eigenvalues().cwiseSqrt().cwiseInverse().asDiagonal() *
                       ei.eigenvectors().transpose();
    Mat6 s = Mat6::Zero();
    s.topLeftCorner<3, 3>() = Mat3::Identity() / std::sqrt(b.body.mass);
    s.bottomRightCorner<3, 3>() = iw_inv_sqrt;
    Mat6 a = s * k * s;
    Eigen::SelfAdjointEigenSolver<Mat6> es(a, Eigen::EigenvaluesOnly);
    return es.eigenvalues().maxCoeff();
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
