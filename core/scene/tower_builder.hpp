#pragma once
/// Four brick walls in running bond bonded at the corners (a tower), optionally with openings
/// bridged by lintels: building-scale scenes of 10³–10⁴ blocks for `cairn make tower|house`.

#include <vector>

#include "scene/scene.hpp"

namespace cairn {

/// A rectangular hole through one wall, from a course up to (not including) another; the course
/// above it gets a lintel that bears one brick thickness on each side.
struct Opening {
    int wall = 0;            ///< 0 front (−y), 1 right (+x), 2 back (+y), 3 left (−x)
    double from = 0.0;       ///< start along the wall from its −x (walls 0, 2) or −y (1, 3) end, m
    double to = 0.0;         ///< end, m (from and to are rounded to whole brick thicknesses)
    int course_from = 0;     ///< first course of the hole
    int course_to = 0;       ///< course above the hole (the lintel's); ≤ courses
};

/// the tower: outer plan length × width in bricks, bricks of length l, thickness l/2, height h
struct TowerSpec {
    int length = 10;                 ///< outer length along x, in brick lengths, ≥ 3
    int width = 10;                  ///< outer width along y, in brick lengths, ≥ 3
    int courses = 40;                ///< count ≥ 1
    double brick_length = 0.24;      ///< m; the wall thickness is half of it
    double brick_height = 0.07;      ///< m
    std::vector<Opening> openings;   ///< holes with lintels (at least one brick from the corners)
};

/// append the fixed slab `base` and the bricks c<course>_w<wall>_<i> course by course; walls 0
/// and 2 run through the corners on even courses, walls 1 and 3 on odd ones. Throws cairn::Error
/// naming the parameter when the plan or an opening does not fit. Returns the first brick's index.
int add_tower(Scene& scene, const TowerSpec& tower);

/// number of bricks of a tower without openings: courses × (2·length + 2·width − 2)
long long tower_brick_count(const TowerSpec& tower);

}  // namespace cairn
