#pragma once
// runs built for the reference kinds' tests: every free block where the scene puts it, the
// reference block moved and turned as a test says, so that a kind measures a known answer
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "scene/scene_io.hpp"

namespace cairn::test {

/// a shipped scene, `name` relative to scenarios/ without ".toml"
inline Scene shipped(const std::string& name) { return load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/" + name + ".toml"); }

/// samples every dt to `duration`: every free block at rest where the scene puts it, except the
/// reference block, moved by d(t) and turned by θ(t) about the world y axis through its centre;
/// probes follow their blocks
inline std::vector<Sample> synthetic_run(const Scene& s, double duration, double dt, const std::function<Vec3(double)>& d,
                                  const std::function<double(double)>& theta) {
    std::vector<Sample> out;
    const int ref = s.reference->block;
    const long n = std::lround(duration / dt);
    for (long i = 0; i <= n; ++i) {
        const double t = double(i) * dt;
        const Quat turn(Eigen::AngleAxisd(theta(t), Vec3::UnitY()));
        Sample x;
        x.t = t;
        for (size_t b = 0; b < s.blocks.size(); ++b) {
            if (s.blocks[b].fixed) continue;
            BlockState st;
            st.position = s.blocks[b].position + (int(b) == ref ? d(t) : Vec3::Zero());
            st.orientation = int(b) == ref ? turn * s.blocks[b].orientation : s.blocks[b].orientation;
            x.blocks.push_back(st);
        }
        for (const auto& p : s.probes) {
            const BlockDef& b = s.blocks[size_t(p.block)];
            x.probes.push_back(p.block == ref ? Vec3(b.position + d(t) + turn * (b.orientation * p.point))
                                              : Vec3(b.position + b.orientation * p.point));
        }
        out.push_back(x);
    }
    return out;
}

inline Vec3 still(double) { return Vec3::Zero(); }
inline double upright(double) { return 0.0; }

}  // namespace cairn::test
