#pragma once
/// A dry brick wall in running bond (one leaf of stretchers, half-brick joints) or English bond
/// (courses of two stretcher leaves alternating with courses of headers, queen closers at the
/// ends), on a fixed base slab or with its first course fixed, with rectangular openings bridged
/// by lintels. In code for tests and benches, and for `cairn make wall`.

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace cairn {

/// how the bricks of successive courses are laid
enum class WallBond {
    running,   ///< stretchers along the wall, one brick thickness thick; odd courses offset by half a brick
    english,   ///< one brick length thick: even courses two leaves of stretchers, odd courses
               ///< headers across the wall with a queen closer (a quarter brick) by each end header
};

/// a rectangular hole through the wall (a door from z0 = 0, or a window); its sides are rounded to
/// whole quarter bricks and its sill and head to whole courses, so no piece of brick is shorter
/// than a quarter brick. Below the top course, the course over it is a lintel bearing half a brick
/// on each side
struct WallOpening {
    double x0 = 0.0;       ///< left side, from the wall's left (−x) end, m
    double z0 = 0.0;       ///< sill, from the foot of the wall, m
    double width = 0.0;    ///< along x, m
    double height = 0.0;   ///< along z, m
};

/// an opening as built: rounded to quarter bricks and whole courses
struct WallHole {
    double x0 = 0.0, x1 = 0.0;      ///< sides, from the wall's left end, m
    int course_from = 0;            ///< first course cut
    int course_to = 0;              ///< course over the hole (the lintel's when < courses)
};

/// the wall; the bricks of course c are named b<c>_<i> (zero-padded, left to right, front leaf
/// first), the lintel over opening k `lintel<k>`, the slab `base`
struct WallSpec {
    int courses = 6;                     ///< courses, count ≥ 1
    int bricks = 6;                      ///< whole bricks per course (wall length / brick length), count ≥ 1
    Vec3 brick{0.4, 0.2, 0.2};           ///< brick length (x), thickness (y), height (z), m; English
                                         ///< bond needs length = 2 × thickness (the wall is a length thick)
    WallBond bond = WallBond::running;   ///< running or English bond
    bool half_bricks = true;             ///< running bond, true: odd courses end in half bricks
                                         ///< (straight ends); false: odd courses shifted by half a brick
    bool base = true;                    ///< true: on a fixed slab `base`; false: course 0 is fixed
    double density = 2600.0;             ///< kg/m³, for placed_kn only
    double gravity = 9.81;               ///< m/s², for placed_kn only
    double placed_kn = 0.0;              ///< N/m³; > 0: each course lowered by the static closure
                                         ///< of the joints under it at this stiffness
    std::vector<WallOpening> openings;   ///< holes through the wall (not with placed_kn)
};

/// append the wall (base first, then course by course from the bottom, left to right); returns
/// the index of the first brick. Throws cairn::Error naming the value when the bond or an opening
/// does not fit
int add_wall(Scene& scene, const WallSpec& wall);

/// the lengths (m) of the bricks of course c from left to right (running bond without openings:
/// half bricks at the ends of odd courses when half_bricks)
std::vector<double> wall_course(const WallSpec& wall, int c);

/// the openings as built (rounded); throws cairn::Error naming the opening when one does not lie
/// half a brick inside the wall's ends and within its height, or two come closer than a brick
std::vector<WallHole> wall_holes(const WallSpec& wall);

/// the thickness of the wall (y), m: a brick thickness in running bond, a brick length in English
double wall_thickness(const WallSpec& wall);

}  // namespace cairn
