#include "block.hpp"

#include <cmath>

namespace cairn::dem {

void Block::update_nodes() {
    Mat3 r = body.q.toRotationMatrix();
    Vec3 w = fixed ? Vec3::Zero() : body.omega();
    for (size_t i = 0; i < local.size(); ++i) {
        Vec3 arm = r * local[i];
        x[i] = body.x + arm;
        v[i] = fixed ? Vec3::Zero() : Vec3(body.v + w.cross(arm));
    }
}

double Block::motion_since_refresh() const {
    Quat dq = body.q * q_at_refresh.conjugate();
    return (body.x - x_at_refresh).norm() + r_max * rotation_vector(dq).norm();
}

Aabb Block::bounds() const {
    Aabb b;
    for (const auto& p : x) b.add(p);
    return b;
}

}  // namespace cairn::dem
