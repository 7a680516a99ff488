#include "scene_compare/block_history.hpp"

#include <algorithm>
#include <cmath>

namespace cairn::scene_compare {

BlockHistory block_history(const std::vector<Sample>& samples, int f) {
    BlockHistory h;
    if (samples.empty() || f < 0 || size_t(f) >= samples.front().blocks.size()) return h;
    const Quat q0 = samples.front().blocks[size_t(f)].orientation.normalized();
    for (const auto& s : samples) {
        if (size_t(f) >= s.blocks.size()) break;
        const BlockState& b = s.blocks[size_t(f)];
        h.t.push_back(s.t);
        h.x.push_back(b.position.x());
        h.y.push_back(b.position.y());
        h.z.push_back(b.position.z());
        // the relative rotation q·q0⁻¹ turns by 2·atan2(|vector part|, |scalar part|)
        const Quat r = b.orientation.normalized() * q0.conjugate();
        h.angle.push_back(2.0 * std::atan2(r.vec().norm(), std::abs(r.w())));
        h.speed.push_back(b.velocity.norm());
    }
    return h;
}

std::vector<FreeBlock> free_blocks(const Scene& scene) {
    std::vector<FreeBlock> out;
    for (size_t i = 0; i < scene.blocks.size(); ++i) {
        const BlockDef& b = scene.blocks[i];
        if (b.fixed) continue;
        FreeBlock fb;
        fb.scene_index = int(i);
        fb.name = b.name.empty() ? "block " + std::to_string(i + 1) : b.name;
        Vec3 lo = b.corners[0], hi = b.corners[0];
        for (const auto& c : b.corners) {
            lo = lo.cwiseMin(c);
            hi = hi.cwiseMax(c);
        }
        fb.size = (hi - lo).minCoeff();
        out.push_back(fb);
    }
    return out;
}

}  // namespace cairn::scene_compare
