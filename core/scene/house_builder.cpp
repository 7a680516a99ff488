#include "scene/house_builder.hpp"

#include <cmath>

namespace cairn {

std::vector<Opening> house_openings(const HouseSpec& house) {
    const TowerSpec& t = house.walls;
    const double l = t.brick_length, h = t.brick_height;
    auto course = [&](double z) { return int(std::lround(z / h)); };
    auto centred = [&](int wall, double width, int c0, int c1) {
        const double len = (wall % 2 == 0 ? t.length : t.width) * l;
        return Opening{wall, 0.5 * (len - width), 0.5 * (len + width), c0, c1};
    };
    std::vector<Opening> out;
    out.push_back(centred(0, house.door_width, 0, course(house.door_height)));
    const int sill = course(house.window_sill), top = course(house.window_sill + house.window_height);
    for (int wall = 1; wall < 4; ++wall) out.push_back(centred(wall, house.window_width, sill, top));
    return out;
}

int add_house(Scene& scene, const HouseSpec& house) {
    TowerSpec t = house.walls;
    std::vector<Opening> holes = house_openings(house);
    holes.insert(holes.end(), t.openings.begin(), t.openings.end());   // the caller's, after the door and windows
    t.openings = holes;
    return add_tower(scene, t);
}

}  // namespace cairn
