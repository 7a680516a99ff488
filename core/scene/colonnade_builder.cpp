#include "scene/colonnade_builder.hpp"

#include <algorithm>

#include "error.hpp"
#include "scene/scene_builder.hpp"

namespace cairn {

int add_colonnade(Scene& scene, const ColonnadeSpec& c) {
    if (c.columns < 2) throw Error("a colonnade needs at least 2 columns, not " + std::to_string(c.columns));
    if (c.spacing < c.width)
        throw Error("the columns' spacing (" + std::to_string(c.spacing) + " m) must be at least their width (" +
                    std::to_string(c.width) + " m)");
    const double span = (c.columns - 1) * c.spacing + c.width, x0 = -0.5 * (c.columns - 1) * c.spacing;
    // the slab reaches a column height beyond each end: room to topple onto it
    add_box(scene, "base", Vec3(span + 2.0 * c.height, std::max(2.0, 2.0 * c.height), 0.5), Vec3(0, 0, -0.25), true);
    const int first = int(scene.blocks.size());
    for (int i = 0; i < c.columns; ++i)
        add_box(scene, "C" + std::to_string(i + 1), Vec3(c.width, c.width, c.height), Vec3(x0 + i * c.spacing, 0, 0.5 * c.height),
                false);
    add_box(scene, "beam", Vec3(span, c.width, c.beam_height), Vec3(0, 0, c.height + 0.5 * c.beam_height), false);
    return first;
}

}  // namespace cairn
