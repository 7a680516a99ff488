#include "run/energy_scale.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/hexahedron.hpp"

namespace cairn {

namespace {

/// the energy scale never falls below this, J (keeps the bounds meaningful for a scene at rest)
constexpr double kMinScale = 1.0;

/// Σ over free blocks of m·g·(block diameter): the energy a block can trade with gravity, J
double gravity_reach(const Scene& scene) {
    const double g = scene.gravity.norm();
    double sum = 0.0;
    for (const auto& b : scene.blocks) {
        if (b.fixed) continue;
        const double density = (b.material >= 0 && b.material < int(scene.materials.size()))
                                   ? scene.materials[b.material].density
                                   : 0.0;
        double diameter = 0.0;
        for (const auto& p : b.corners)
            for (const auto& q : b.corners) diameter = std::max(diameter, (p - q).norm());
        sum += mass_properties(b.corners, density).mass * g * diameter;
    }
    return sum;
}

}  // namespace

EnergyScale::EnergyScale(const Scene& scene) : gravity_reach_(gravity_reach(scene)) {}

EnergyBounds EnergyScale::add(const Energies& e) {
    const double motion = std::abs(e.kinetic) + std::abs(e.contact) + std::abs(e.strain);
    if (first_) {
        motion_max_ = initial_motion_ = motion;
        potential_min_ = potential_max_ = potential_first_ = e.potential;
        first_ = false;
    }
    potential_min_ = std::min(potential_min_, e.potential);
    potential_max_ = std::max(potential_max_, e.potential);
    work_max_ = std::max(work_max_, std::abs(e.external));
    EnergyBounds b;
    b.motion = std::max(kMinScale, motion_max_ + std::abs(e.external) + (potential_max_ - potential_min_));
    b.growth = std::max(kMinScale, initial_motion_ + work_max_ + (potential_first_ - potential_min_)) + gravity_reach_;
    motion_max_ = std::max(motion_max_, motion);
    return b;
}

}  // namespace cairn
