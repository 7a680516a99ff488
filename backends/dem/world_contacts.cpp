// the world's contact points for output: read from the candidates' kept forces (the paper
// scheme's hitting points, the overlap scheme's sub-contacts)
#include "world.hpp"

namespace cairn::dem {

std::vector<ContactPoint> World::contact_points() const {
    std::vector<ContactPoint> out;
    for (const auto& c : contacts_.candidates()) {
        const Block& hb = blocks_[c.hit_block];
        const Block& tb = blocks_[c.target_block];
        for (const auto& p : c.forces) {
            ContactPoint cp;
            // the hitting point on the hitting block's face; the target face's outward normal
            cp.position = quad_point(hb.face_quad(c.hit_face), hb.hits[c.hit_face][p.point].xi);
            cp.normal = quad_normal(tb.face_quad(p.target_face), p.target_xi);
            cp.normal_force = p.force.dot(cp.normal) * cp.normal;
            cp.shear_force = p.force - cp.normal_force;
            cp.block_a = c.hit_block;
            cp.block_b = c.target_block;
            out.push_back(cp);
        }
        // overlap scheme: each sub-contact at its point of action on the hitting block
        for (const auto& p : c.sub_forces) {
            ContactPoint cp;
            cp.position = Vec3::Zero();
            for (int i = 0; i < p.hit.count; ++i) cp.position += p.hit.w[i] * hb.x[p.hit.node[i]];
            cp.normal = p.normal;
            cp.normal_force = p.force.dot(cp.normal) * cp.normal;
            cp.shear_force = p.force - cp.normal_force;
            cp.block_a = c.hit_block;
            cp.block_b = c.target_block;
            out.push_back(cp);
        }
    }
    return out;
}

}  // namespace cairn::dem
