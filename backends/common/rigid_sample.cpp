#include "rigid_sample.hpp"

namespace cairn {

Sample rigid_sample(double t, const std::vector<RigidBlock>& blocks, const Scene& scene,
                    const std::function<BlockState(const RigidBlock&)>& state, const std::function<Vec3(int)>& com,
                    const std::function<Quat(int)>& orientation) {
    Sample s;
    s.t = t;
    for (const RigidBlock& b : blocks)
        if (!b.fixed) add_block_state(s, b, state(b), scene.gravity);
    for (const ProbeDef& p : scene.probes)
        s.probes.push_back(block_point_world(blocks[size_t(p.block)], com(p.block), orientation(p.block), p.point));
    return s;
}

std::string non_finite_block(const std::vector<RigidBlock>& blocks, double t, const std::function<Vec3(int)>& com) {
    for (const RigidBlock& b : blocks)
        if (!b.fixed && !com(b.index).allFinite())
            return "block '" + b.name + "' position is not finite at t = " + std::to_string(t) + " s";
    return {};
}

}  // namespace cairn
