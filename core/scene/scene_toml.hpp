#pragma once
/// Writing a Scene built in code as a plain, editable scene file (what the generators of
/// `cairn make` print): the run, materials, contact law and blocks; loads, ground motion, probes
/// and references are left for the user to add.

#include <string>

#include "scene/scene.hpp"

namespace cairn {

/// the [blocks.*] tables: axis-aligned boxes by size and position, any other block by its world
/// corners (shape = "hexahedron"), every block of `material`; numbers to 10 significant digits
std::string blocks_toml(const Scene& scene, const std::string& material);

/// a whole scene file: `comment` (each line prefixed with "# "), description, gravity, [run],
/// [materials.*] (the first one is every block's material), [contact], then blocks_toml
std::string scene_toml(const Scene& scene, const std::string& comment);

}  // namespace cairn
