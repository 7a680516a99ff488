// the world's contact points for output: read from the candidates' kept forces (the paper
// scheme's hitting points, the overlap scheme's sub-contacts)
#include "world.hpp"

namespace cairn::dem {

std::vector<ContactPoint> World::contact_points() const {
    std::vector<ContactPoint> out;
    for (const auto& c : contacts_.candidates()) {
        const Block& hb = blocks_[c.hit_block];
        const Block& tb = blocks_[c.target_block];
        // a force on the hitting block at `position`, split along the target face's outward normal
        auto add = [&](const Vec3& position, const Vec3& normal, const Vec3& force) {
            ContactPoint cp;
            cp.position = position;
            cp.normal = normal;
            cp.normal_force = force.dot(normal) * normal;
            cp.shear_force = force - cp.normal_force;
            cp.block_a = c.hit_block;
            cp.block_b = c.target_block;
            out.push_back(cp);
        };
        // paper scheme: the hitting point on the hitting block's face
        for (const auto& p : c.forces)
            add(quad_point(hb.face_quad(c.hit_face), hb.hits[c.hit_face][p.point].xi),
                quad_normal(tb.face_quad(p.target_face), p.target_xi), p.force);
        // overlap scheme: each sub-contact at its point of action on the hitting block
        for (const auto& p : c.sub_forces) {
            if (p.twist) continue;   // a couple about its sub-contact's normal: no force of its own
            Vec3 position = Vec3::Zero();
            for (int i = 0; i < p.hit.count; ++i) position += p.hit.w[i] * hb.x[p.hit.node[i]];
            add(position, p.normal, p.force);
        }
    }
    return out;
}

}  // namespace cairn::dem
