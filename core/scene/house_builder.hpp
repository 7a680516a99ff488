#pragma once
/// A one-room house: the four bonded walls of a tower with a door in the front wall and a window
/// centred in each of the three others, each bridged by a lintel (`cairn make house`).

#include "scene/tower_builder.hpp"

namespace cairn {

/// the house: the tower's plan and bricks (its openings are kept, after the door and windows) and the holes, m
struct HouseSpec {
    TowerSpec walls{16, 12, 36, 0.24, 0.07, {}};   ///< plan in bricks, courses, brick size
    double door_width = 0.96;      ///< m, centred in the front wall (wall 0)
    double door_height = 2.0;      ///< m from the base, rounded to whole courses
    double window_width = 0.72;    ///< m, centred in walls 1, 2, 3
    double window_sill = 0.9;      ///< m from the base, rounded to whole courses
    double window_height = 1.0;    ///< m, rounded to whole courses
};

/// the openings of the house in tower form
std::vector<Opening> house_openings(const HouseSpec& house);

/// append the house (base, then the bricks and lintels course by course); returns the first brick
int add_house(Scene& scene, const HouseSpec& house);

}  // namespace cairn
