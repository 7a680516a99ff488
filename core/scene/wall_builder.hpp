#pragma once
/// A dry brick wall in running bond: courses of bricks laid along x, on a fixed base slab or with
/// its first course fixed. In code for tests and benches, and for `cairn make wall`.

#include "scene/scene.hpp"

namespace cairn {

/// the wall; bricks of course c are named b<c>_<i> (zero-padded), the slab `base`
struct WallSpec {
    int courses = 6;                     ///< courses, count ≥ 1
    int bricks = 6;                      ///< whole bricks per course, count ≥ 1
    Vec3 brick{0.4, 0.2, 0.2};           ///< brick length (x), thickness (y), height (z), m
    bool half_bricks = true;             ///< true: odd courses end in half bricks (straight ends);
                                         ///< false: odd courses shifted by half a brick (overhang)
    bool base = true;                    ///< true: on a fixed slab `base`; false: course 0 is fixed
    double density = 2600.0;             ///< kg/m³, for placed_kn only
    double gravity = 9.81;               ///< m/s², for placed_kn only
    double placed_kn = 0.0;              ///< N/m³; > 0: each course lowered by the static closure
                                         ///< of the joints under it at this stiffness
};

/// append the wall (base first, then course by course from the bottom, left to right); returns
/// the index of the first brick
int add_wall(Scene& scene, const WallSpec& wall);

/// the lengths (m) of the bricks of course c from left to right (half bricks at the ends of odd
/// courses when half_bricks)
std::vector<double> wall_course(const WallSpec& wall, int c);

}  // namespace cairn
