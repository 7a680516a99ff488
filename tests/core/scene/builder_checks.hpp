#pragma once
// shared checks of the scene generators: the scene written as TOML and read back by the loader
// (which refuses overlaps at t = 0), the deepest overlap of any pair, the free blocks' mass and
// centre of mass

#include <string>

#include "geometry/hexahedron.hpp"
#include "geometry/overlap.hpp"
#include "scene/scene_io.hpp"
#include "scene/scene_toml.hpp"

namespace cairn::test {

// a scene built in code with one material and a contact law, ready for scene_toml
inline Scene builder_scene() {
    Scene s;
    s.materials.push_back({"stone", 2000.0, 30e9, 0.2});
    s.contact.kn = s.contact.ks = 1e9;
    s.contact.friction = 0.7;
    return s;
}

// the scene as the loader reads it back from its TOML text
inline Scene reloaded(const Scene& s) { return parse_scene(scene_toml(s, "test"), "<builder test>"); }

// deepest overlap (m) of any two blocks of a small scene, fixed pairs included; ≤ 0 when they
// touch or are apart (brute force over all pairs)
inline double deepest_overlap(const Scene& s) {
    double deepest = -1e300;
    for (size_t i = 0; i < s.blocks.size(); ++i)
        for (size_t j = i + 1; j < s.blocks.size(); ++j) {
            const BlockDef &a = s.blocks[i], &b = s.blocks[j];
            deepest = std::max(deepest, overlap_depth(placed_corners(a.corners, a.position, a.orientation),
                                                      placed_corners(b.corners, b.position, b.orientation)));
        }
    return deepest;
}

// total mass (kg) and centre of mass (world, m) of the free blocks
struct FreeMass {
    double mass = 0.0;
    Vec3 centre = Vec3::Zero();
    int count = 0;
};
inline FreeMass free_mass(const Scene& s) {
    FreeMass out;
    for (const BlockDef& b : s.blocks) {
        if (b.fixed) continue;
        const MassProperties mp = mass_properties(b.corners, s.materials[size_t(b.material)].density);
        out.mass += mp.mass;
        out.centre += mp.mass * (b.position + b.orientation * mp.centre);
        ++out.count;
    }
    out.centre /= out.mass;
    return out;
}

}  // namespace cairn::test
