#pragma once
// Running the dem backend directly (without the runner) and reading signals out of it.

#include <functional>
#include <memory>

#include "dem/block_builder.hpp"
#include "dem/contact.hpp"
#include "dem/dem_backend.hpp"

namespace cairn::test {

/// a built dem backend for `scene`
inline std::unique_ptr<Backend> build_dem(const Scene& scene) {
    auto b = dem_backend_info().make();
    b->build(scene, RunOptions{});
    return b;
}

/// step until `duration` (s), calling `on_sample` after every step; false if a step was unstable
inline bool run_dem(Backend& b, double duration, const std::function<void(const Sample&)>& on_sample) {
    const long long steps = (long long)std::ceil(duration / b.time_step() - 1e-9);
    on_sample(b.sample());
    for (long long i = 0; i < steps; ++i) {
        if (b.step() != StepStatus::ok) return false;
        on_sample(b.sample());
    }
    return true;
}

/// the resultant contact force (N) on block `on` of a scene, from one contact evaluation (0.05 m
/// margin, dt 1e-4 s) of freshly built blocks
inline Vec3 contact_resultant(const Scene& s, int on) {
    std::vector<dem::Block> blocks;
    for (const auto& d : s.blocks) blocks.push_back(dem::make_block(d, s));
    dem::ContactSet cs;
    cs.configure(s.contact, 0.05);
    cs.refresh(blocks);
    cs.apply(blocks, 1e-4);
    Vec3 f = Vec3::Zero();
    for (const auto& fn : blocks[size_t(on)].f) f += fn;
    return f;
}

}  // namespace cairn::test
