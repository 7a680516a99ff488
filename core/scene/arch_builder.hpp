#pragma once
/// A semicircular arch of N voussoirs with radial joints (general hexahedra) on two fixed
/// abutments: in code for tests, and as the TOML text of the shipped arch scenes.

#include <string>
#include <vector>

#include "geometry/hexahedron.hpp"
#include "scene/scene.hpp"

namespace cairn {

/// the arch: centreline radius, thickness and depth; voussoirs V1 (left springing) … VN
struct ArchSpec {
    int voussoirs = 25;          ///< N ≥ 1
    double radius = 2.0;         ///< centreline radius R, m
    double thickness = 0.2;      ///< radial thickness t, m (< 2R)
    double depth = 0.5;          ///< along y, m
};

/// the world corners of voussoir i (0 … N−1), hex8 order: corners 0-3 on the intrados, 4-7 on the
/// extrados; voussoir i spans the angles [iπ/N, (i+1)π/N] from the left springing (x = −R, z = 0)
Corners arch_voussoir(const ArchSpec& arch, int i);

/// append the voussoirs V1 … VN (hexahedra, material 0) and the fixed abutments `left` and
/// `right` (1 × (depth + 0.5) × 0.5 m boxes under the springings); returns the index of V1
int add_arch(Scene& scene, const ArchSpec& arch);

/// the [blocks.*] tables of add_arch as TOML text (corners to 1e-9 m), for scene files
std::string arch_blocks_toml(const ArchSpec& arch, const std::string& material);

}  // namespace cairn
