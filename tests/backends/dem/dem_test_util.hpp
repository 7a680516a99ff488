#pragma once
// Running the dem backend directly (without the runner) and reading signals out of it.

#include <functional>
#include <memory>

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

}  // namespace cairn::test
