#include "run/energy_scale.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/hexahedron.hpp"

namespace cairn {

namespace {

/// the energy scale never falls below this, J (keeps the bounds meaningful for a scene at rest)
constexpr double kMinScale = 1.0;

/// m·g·(block diameter) of each free block: the energy a block can trade with gravity, J
std::vector<double> gravity_reaches(const Scene& scene) {
    const double g = scene.gravity.norm();
    std::vector<double> reach;
    for (const auto& b : scene.blocks) {
        if (b.fixed) continue;
        const double density = (b.material >= 0 && b.material < int(scene.materials.size()))
                                   ? scene.materials[b.material].density
                                   : 0.0;
        double diameter = 0.0;
        for (const auto& p : b.corners)
            for (const auto& q : b.corners) diameter = std::max(diameter, (p - q).norm());
        reach.push_back(mass_properties(b.corners, density).mass * g * diameter);
    }
    return reach;
}

}  // namespace

EnergyScale::EnergyScale(const Scene& scene) {
    for (double r : gravity_reaches(scene)) {
        gravity_reach_ += r;
        block_reach_ = std::max(block_reach_, r);
    }
}

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
    b.created = std::max(b.motion, block_reach_);
    motion_max_ = std::max(motion_max_, motion);
    return b;
}

}  // namespace cairn
