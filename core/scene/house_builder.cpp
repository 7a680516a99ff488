#include "scene/house_builder.hpp"

#include <cmath>
#include <string>

#include "error.hpp"
#include "output/number_format.hpp"

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

namespace {

std::string metres(double x) { return message_number(x) + " m"; }

/// refuses a door or windows that do not fit the house's courses, naming the options that set them
/// (the tower's own check would call them openings 0 and 1 and the house a tower)
void check_door_and_windows(const HouseSpec& house, const std::vector<Opening>& holes) {
    const int courses = house.walls.courses;
    const std::string of = " the house's " + std::to_string(courses) + " courses of " + metres(house.walls.brick_height);
    const Opening& door = holes[0];
    if (door.course_to < 1 || door.course_to > courses)
        throw Error("the door (--door-height " + metres(house.door_height) + ", " + std::to_string(door.course_to) +
                    " courses) does not fit" + of + ": lower it or add --courses");
    const Opening& window = holes[1];
    if (window.course_to <= window.course_from || window.course_to > courses)
        throw Error("the windows (--window-sill " + metres(house.window_sill) + ", --window-height " +
                    metres(house.window_height) + ": courses " + std::to_string(window.course_from) + " to " +
                    std::to_string(window.course_to) + ") do not fit" + of + ": lower them or add --courses");
}

}  // namespace

int add_house(Scene& scene, const HouseSpec& house) {
    TowerSpec t = house.walls;
    std::vector<Opening> holes = house_openings(house);
    check_door_and_windows(house, holes);
    holes.insert(holes.end(), t.openings.begin(), t.openings.end());   // the caller's, after the door and windows
    t.openings = holes;
    return add_tower(scene, t);
}

}  // namespace cairn
