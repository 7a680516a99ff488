#include "block.hpp"

#include <algorithm>
#include <cmath>

namespace cairn::dem {

int Block::face_at(int s, const Vec2& xi) const {
    const int nu = mesh.side_nu[s], nv = mesh.side_nv[s];
    int u = std::clamp(int(std::floor(0.5 * (xi[0] + 1.0) * nu)), 0, nu - 1);
    int v = std::clamp(int(std::floor(0.5 * (xi[1] + 1.0) * nv)), 0, nv - 1);
    return mesh.side_grid[s][v * nu + u];
}

Vec3 Block::world_point(const Vec3& frame_point) const {
    return body.x + body.q * (frame_point - com_in_frame);
}

void Block::update_nodes() {
    if (deformable) {
        Mat3 r;
        deformable->pose(x, body.x, r);
        body.q = Quat(r);
        return;
    }
    const Mat3 r = body.q.toRotationMatrix();
    rotation = r;
    const Vec3 w = fixed ? Vec3::Zero() : body.omega(r);
    spin = w;
    for (size_t i = 0; i < local.size(); ++i) {
        Vec3 arm = r * local[i];
        x[i] = body.x + arm;
        v[i] = fixed ? Vec3::Zero() : Vec3(body.v + w.cross(arm));
    }
    // the frame of 4 corners in which node_weights gives a point's affine weights
    const int n0 = mesh.node(0, 0, 0);
    Mat3 e;
    e.col(0) = x[mesh.node(1, 0, 0)] - x[n0];
    e.col(1) = x[mesh.node(0, 1, 0)] - x[n0];
    e.col(2) = x[mesh.node(0, 0, 1)] - x[n0];
    corner_inverse = e.inverse();
}

double Block::turn_since_refresh() const {
    return rotation_vector(body.q * q_at_refresh.conjugate()).norm();
}

Aabb Block::bounds() const {
    Aabb b;
    for (const auto& p : x) b.add(p);
    return b;
}

}  // namespace cairn::dem
