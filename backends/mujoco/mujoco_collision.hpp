#pragma once
/// MuJoCo 2.2.2's mesh collider gives one contact per pair, so a face-on-face joint of general
/// hexahedra hinges; box-mesh and mesh-mesh pairs of a cairn model go through cairn's
/// face-clipping collider (common/hexahedron_contact) instead, through MuJoCo's collision table.
/// Box-box pairs go there too: MuJoCo's box-box collider gives duplicate and phantom deep points
/// for two equal boxes face on face (docs/backends.md).

#include <mujoco/mujoco.h>

#include <vector>

#include "rigid_blocks.hpp"

namespace cairn {

/// the blocks behind a model's geoms, for the collider
struct MujocoHexahedra {
    const mjModel* model = nullptr;            ///< the model these geoms belong to
    std::vector<const RigidBlock*> geom_block; ///< block per geom id (null: not a block)
    /// factor on the overlap a box-box pair reports as its distance: 0.5 keeps MuJoCo's own box-box
    /// convention (half the overlap), which the rigid mode's solref was set against
    double box_depth_scale = 1.0;
};

/// puts cairn's collider into mjCOLLISIONFUNC for box-box, box-mesh and mesh-mesh pairs (once per
/// process); models other than the one made current, and geoms that are not blocks, fall through
/// to MuJoCo's own function
void install_hexahedron_collider();

/// makes `h` the model the collider serves on this thread until the returned guard goes out of scope
class CurrentHexahedra {
public:
    explicit CurrentHexahedra(const MujocoHexahedra* h);
    ~CurrentHexahedra();
    CurrentHexahedra(const CurrentHexahedra&) = delete;
    CurrentHexahedra& operator=(const CurrentHexahedra&) = delete;

private:
    const MujocoHexahedra* previous_;
};

}  // namespace cairn
