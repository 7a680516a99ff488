#pragma once
// The overlap scheme's force against its stored energy: central finite differences of U over the
// pose of block 0 of a scene (block 1 fixed), from one contact evaluation of freshly built blocks.

#include <sstream>
#include <string>
#include <vector>

#include "dem/block_builder.hpp"
#include "dem/contact.hpp"

namespace cairn::test {

// energy, resultant force and moment about the centre on free block 0 of a scene (block 1 fixed),
// from one contact evaluation
struct BlockLoad {
    double energy = 0.0;
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
};
inline BlockLoad block_load(const Scene& s) {
    std::vector<dem::Block> blocks;
    for (const auto& d : s.blocks) blocks.push_back(dem::make_block(d, s));
    dem::ContactSet cs;
    cs.configure(s.contact, 0.05);
    cs.refresh(blocks);
    BlockLoad r;
    r.energy = cs.apply(blocks, 1e-4).stored;
    const dem::Block& a = blocks[0];
    for (size_t i = 0; i < a.f.size(); ++i) {
        r.force += a.f[i];
        r.moment += (a.x[i] - a.body.x).cross(a.f[i]);
    }
    return r;
}

// the largest gap between the scheme's force and moment on block 0 and −∇U by central
// differences (steps h_x in m and h_r in rad), relative to |force| and |force|·r
struct Gap {
    double force = 0.0, moment = 0.0;
    Vec3 f = Vec3::Zero(), m = Vec3::Zero(), f_fd = Vec3::Zero(), m_fd = Vec3::Zero();
};
inline Gap gradient_gap(const Scene& s, double h_x, double h_r, double lever) {
    Gap g;
    const BlockLoad at = block_load(s);
    g.f = at.force;
    g.m = at.moment;
    for (int k = 0; k < 3; ++k) {
        Scene plus = s, minus = s;
        plus.blocks[0].position += h_x * Vec3::Unit(k);
        minus.blocks[0].position -= h_x * Vec3::Unit(k);
        g.f_fd[k] = -(block_load(plus).energy - block_load(minus).energy) / (2.0 * h_x);
        // a turn about the centre of mass (the block frame's origin for a box)
        plus = s, minus = s;
        plus.blocks[0].orientation = Quat(Eigen::AngleAxisd(h_r, Vec3::Unit(k))) * s.blocks[0].orientation;
        minus.blocks[0].orientation = Quat(Eigen::AngleAxisd(-h_r, Vec3::Unit(k))) * s.blocks[0].orientation;
        g.m_fd[k] = -(block_load(plus).energy - block_load(minus).energy) / (2.0 * h_r);
    }
    g.force = (g.f - g.f_fd).norm() / g.f.norm();
    g.moment = (g.m - g.m_fd).norm() / (g.f.norm() * lever);
    return g;
}

/// the scheme's force and moment beside −∇U, for a failure message
inline std::string show(const Gap& g) {
    std::ostringstream o;
    o << "force " << g.f.transpose() << " vs −∇U " << g.f_fd.transpose() << "; moment " << g.m.transpose() << " vs "
      << g.m_fd.transpose();
    return o.str();
}

}  // namespace cairn::test
