#pragma once
/// Building scenes in code (tests, benchmarks, sweeps): the same Scene a file would give.

#include <string>

#include "scene/scene.hpp"

namespace cairn {

/// append a rigid box block of edge lengths `size` (m), centred at `centre` (m, world) and turned
/// by `orientation`, with material 0; returns its index
int add_box(Scene& scene, const std::string& name, const Vec3& size, const Vec3& centre, bool fixed,
            const Quat& orientation = Quat::Identity());

}  // namespace cairn
