#pragma once
/// Which variants `cairn compare` runs for a user scene: the variants `cairn validate` would run
/// when the scene has a [reference], otherwise every block model of dem and both contact modes of
/// each reference engine (there is no reference to restrict them).

#include <string>
#include <vector>

#include "validation/plan.hpp"

namespace cairn::scene_compare {

/// the variants of `scene` among `backends` (in that order) whose block model is `model` ("rigid",
/// "deformable" or "both"); the reference engines have rigid blocks only
std::vector<validation::Variant> compare_variants(const Scene& scene, const std::vector<BackendInfo>& backends,
                                                  const std::string& model);

/// a line for the user before the runs when one variant will take far longer than the others:
/// siconos's step grows as the square of the free blocks (docs/backends.md, "Siconos": 71 ms a
/// step with 34 free bricks), so a wall of a few dozen blocks keeps it busy for hours; the
/// estimate, its steps and how to leave it out, or empty below ten minutes of one core
std::string long_run_note(const Scene& scene, const std::vector<validation::Variant>& variants);

}  // namespace cairn::scene_compare
