#pragma once
/// Loads that change faster than the contact springs can follow: on an undamped contact they
/// leave the springs ringing, and ringing ratchets a block along even below friction
/// (docs/dem.md, "Holding under loads").

#include <optional>

#include "scene/scene.hpp"

namespace cairn::dem {

/// A load step after t = 0 that the contact springs cannot follow.
struct SuddenLoad {
    double time = 0.0;   ///< s: when it comes
    int load = 0;        ///< index into Scene::loads
};

/// The first change after t = 0 of a load on a free block by more than 5 % of that block's weight
/// within one `period` (s, the contact springs' period): a load with `start > 0` and a ramp shorter
/// than the period, or two samples of a load's history (its first and last against the zero
/// outside its span) that close in time; none when every load changes slowly. Loads acting at
/// t = 0 are taken in by the settling and are not counted.
std::optional<SuddenLoad> first_sudden_load(const Scene& scene, double period);

}  // namespace cairn::dem
