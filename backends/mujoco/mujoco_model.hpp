#pragma once
/// The MJCF text of a scene for MuJoCo 2.2.2: one free body per free block (body frame = block
/// axes at the centre of mass), fixed blocks as world geoms, boxes as box geoms, general
/// hexahedra as mesh geoms.

#include <string>
#include <vector>

#include "rigid_blocks.hpp"
#include "scene/scene.hpp"

namespace cairn {

/// contact and solver parameters written into the model
struct MujocoParameters {
    double dt = 1e-4;                     ///< s
    std::string cone = "pyramidal";       ///< "pyramidal" or "elliptic"
    std::string solver = "Newton";        ///< constraint solver: "Newton", "CG" or "PGS"
    int iterations = 100;                 ///< solver iterations
    int noslip_iterations = 0;            ///< iterations of the no-slip post-solver (0 = off)
    double tolerance = 1e-10;             ///< solver tolerance
    double impedance = 0.99;              ///< constant solimp d (dmin = dmax)
    double solref[2] = {0.002, 1.0};      ///< (timeconst s, dampratio) per geom; matched mode
                                          ///< overwrites each contact's solref after collision
    double impratio = 1.0;                ///< friction-to-normal impedance ratio (elliptic cone)
    int nconmax = 100;                    ///< contact list size
    int njmax = 500;                      ///< constraint rows
};

/// the MJCF text of `scene`
std::string mujoco_xml(const Scene& scene, const std::vector<RigidBlock>& blocks, const MujocoParameters& p);

}  // namespace cairn
