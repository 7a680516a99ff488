#include "scene/scene_builder.hpp"

#include "geometry/hexahedron.hpp"

namespace cairn {

int add_box(Scene& scene, const std::string& name, const Vec3& size, const Vec3& centre, bool fixed,
            const Quat& orientation) {
    BlockDef b;
    b.name = name;
    b.shape = Shape::box;
    b.size = size;
    b.corners = box_corners(size);
    b.position = centre;
    b.orientation = orientation;
    b.fixed = fixed;
    scene.blocks.push_back(b);
    return int(scene.blocks.size()) - 1;
}

}  // namespace cairn
