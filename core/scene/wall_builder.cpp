#include "scene/wall_builder.hpp"

#include <cstdio>

#include "scene/scene_builder.hpp"

namespace cairn {

std::vector<double> wall_course(const WallSpec& wall, int c) {
    const double l = wall.brick.x();
    std::vector<double> out;
    if (c % 2 == 1 && wall.half_bricks) {
        out.push_back(0.5 * l);
        for (int i = 1; i < wall.bricks; ++i) out.push_back(l);
        out.push_back(0.5 * l);
    } else {
        out.assign(size_t(wall.bricks), l);
    }
    return out;
}

int add_wall(Scene& scene, const WallSpec& wall) {
    const double l = wall.brick.x(), t = wall.brick.y(), h = wall.brick.z();
    const double length = l * wall.bricks;
    if (wall.base) add_box(scene, "base", Vec3(length + 1.0, t + 0.8, 0.5), Vec3(0, 0, -0.25), true);
    const int first = int(scene.blocks.size());
    double z = 0.0;
    char name[48];
    for (int c = 0; c < wall.courses; ++c) {
        // the joint under course c carries the courses above it: pressure (courses − c)·ρ g h
        if (wall.placed_kn > 0.0) z -= (wall.courses - c) * wall.density * wall.gravity * h / wall.placed_kn;
        double x = -0.5 * length + (c % 2 == 1 && !wall.half_bricks ? 0.5 * l : 0.0);
        const auto course = wall_course(wall, c);
        for (size_t i = 0; i < course.size(); ++i) {
            std::snprintf(name, sizeof name, "b%03d_%03zu", c, i);
            add_box(scene, name, Vec3(course[i], t, h), Vec3(x + 0.5 * course[i], 0, z + 0.5 * h),
                    !wall.base && c == 0);
            x += course[i];
        }
        z += h;
    }
    return first;
}

}  // namespace cairn
