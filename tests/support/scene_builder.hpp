#pragma once
// The shared scene library of the tests and benches, built in code: the paper's stone, boxes, a
// stack of cubes, the rocking block (the brick wall is compare/bench's wall_scene), with
// validation left to the loader's own tests.

#include <cmath>
#include <string>

#include "geometry/hexahedron.hpp"
#include "scene/scene.hpp"
#include "scene/scene_builder.hpp"

namespace cairn::test {

/// the paper's stone: 2600 kg/m³, E = 30 GPa, ν = 0.2 (docs/physics.md)
inline Material stone() { return {"stone", 2600.0, 30e9, 0.2}; }

/// a scene with the paper's stone (2600 kg/m³, E = 30 GPa, ν = 0.2) and contact kn = ks = 3e7
inline Scene stone_scene(double friction = 0.6) {
    Scene s;
    s.name = "test";
    s.source = "<test>";
    s.materials.push_back(stone());
    s.contact.kn = 3e7;
    s.contact.ks = 3e7;
    s.contact.friction = friction;
    s.run.duration = 1.0;
    s.run.settle = false;   // the tests place their blocks as they mean them to start
    return s;
}

/// add a box block (cairn::add_box); `position` is the box centre, m
using cairn::add_box;

/// a box of `size` rotated by `angle` (rad) about the world y axis through the point `pivot`,
/// having first been placed with its centre at `position`
inline int add_box_rotated_about(Scene& s, const std::string& name, const Vec3& size, const Vec3& position,
                                 double angle, const Vec3& pivot, bool fixed) {
    Quat q(Eigen::AngleAxisd(angle, Vec3::UnitY()));
    Vec3 centre = pivot + q * (position - pivot);
    return add_box(s, name, size, centre, fixed, q);
}

/// a stack of n free cubes of edge `edge` (m) named A, B, C, ... bottom first, on a fixed cube
/// "base" whose top is at z = 0; returns the index of the bottom cube
inline int add_cube_stack(Scene& s, int n, double edge = 1.0) {
    const int first = int(s.blocks.size());
    for (int i = 0; i < n; ++i)
        add_box(s, std::string(1, char('A' + i)), Vec3(edge, edge, edge), Vec3(0, 0, (i + 0.5) * edge), false);
    add_box(s, "base", Vec3(edge, edge, edge), Vec3(0, 0, -0.5 * edge), true);
    return first;
}

/// the rocking block: A, 0.2 x 0.7 x 1.0 m, resting on its x = +0.1 m bottom edge on a fixed base
/// B (top at z = 0), tilted by theta0 (rad) about y; μ = 1 (no sliding at the pivot)
inline Scene rocking_block(double theta0) {
    Scene s = stone_scene(1.0);
    s.name = "rocking";
    add_box(s, "A", Vec3(0.2, 0.7, 1.0), Vec3::Zero(), false);
    add_box(s, "B", Vec3(1.0, 1.0, 0.5), Vec3(0, 0, -0.25), true);
    BlockDef& a = s.blocks[0];
    a.orientation = Quat(Eigen::AngleAxisd(theta0, Vec3::UnitY()));
    // pivot: block-frame point (0.1, 0, -0.5) placed at (0.1, 0, 0)
    a.position = Vec3(0.1, 0.0, 0.0) - a.orientation * Vec3(0.1, 0.0, -0.5);
    return s;
}

}  // namespace cairn::test
