// the world's contact points for output: read from the candidates' kept forces
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
    }
    return out;
}

}  // namespace cairn::dem
