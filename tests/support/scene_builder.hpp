#pragma once
// Scenes built in code for tests: the paper's stone, boxes, probes and loads, with validation
// left to the loader's own tests.

#include <cmath>
#include <string>

#include "geometry/hexahedron.hpp"
#include "scene/scene.hpp"
#include "scene/scene_builder.hpp"

namespace cairn::test {

/// a scene with the paper's stone (2600 kg/m³, E = 30 GPa, ν = 0.2) and contact kn = ks = 3e7
inline Scene stone_scene(double friction = 0.6) {
    Scene s;
    s.name = "test";
    s.source = "<test>";
    s.materials.push_back({"stone", 2600.0, 30e9, 0.2});
    s.contact.kn = 3e7;
    s.contact.ks = 3e7;
    s.contact.friction = friction;
    s.run.duration = 1.0;
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

}  // namespace cairn::test
