#include "scene/column_builder.hpp"

#include <algorithm>

#include "scene/scene_builder.hpp"

namespace cairn {

int add_column(Scene& scene, const ColumnSpec& column) {
    if (column.base) {
        const double side = std::max(2.0, 4.0 * column.width);
        add_box(scene, "base", Vec3(side, side, 0.5), Vec3(0, 0, -0.25), true);
    }
    const int first = int(scene.blocks.size());
    for (int i = 0; i < column.drums; ++i)
        add_box(scene, "D" + std::to_string(i + 1), Vec3(column.width, column.width, column.drum_height),
                Vec3(0, 0, (i + 0.5) * column.drum_height), !column.base && i == 0);
    return first;
}

}  // namespace cairn
