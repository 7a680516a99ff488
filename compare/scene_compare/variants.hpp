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

}  // namespace cairn::scene_compare
