#pragma once
/// A semicircular, pointed (two-centred) or segmental arch of N voussoirs with radial joints (general hexahedra) on two
/// fixed springers: in code for tests, as the TOML text of the shipped arch scenes, `cairn make arch`.

#include <cmath>
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
    double angle = M_PI;         ///< angle the arch subtends, rad, in (0, π]; π = semicircular
    double pointed = 0.0;        ///< ≥ 0, dimensionless; > 0 (with angle = π): a pointed arch whose
                                 ///< left half is centred pointed·2R right of the axis and the right
                                 ///< half as far left, each of centreline radius R + pointed·2R
};

/// the world corners of voussoir i (0 … N−1), hex8 order: corners 0-3 on the intrados, 4-7 on the
/// extrados; voussoir i spans the angles [a0 + iβ/N, a0 + (i+1)β/N] (β = angle, a0 = (π − β)/2)
/// measured from the −x axis about the centre (0, 0, 0). Pointed: the joints of each half are radial
/// about its own centre at equal steps of angle up to the crown; an odd N has a keystone across the
/// crown, an even N a vertical joint there
Corners arch_voussoir(const ArchSpec& arch, int i);

/// append the voussoirs V1 … VN (hexahedra, material 0) and the fixed springers `left` and
/// `right`: for a semicircular arch max(1, 2t) × (depth + 0.5) × 0.5 m boxes under the springings;
/// for a segmental one hexahedra whose top is the inclined springing joint and whose bottom lies
/// 0.5 m below the intrados springing point; returns the index of V1
int add_arch(Scene& scene, const ArchSpec& arch);

/// the [blocks.*] tables of add_arch as TOML text (blocks_toml), for scene files
std::string arch_blocks_toml(const ArchSpec& arch, const std::string& material);

}  // namespace cairn
