#pragma once
/// A column of square drums stacked on a fixed base slab (or with its first drum fixed): in code
/// for tests, and for `cairn make column`.

#include "scene/scene.hpp"

namespace cairn {

/// the column; drums D1 (bottom) … DN, the slab `base`
struct ColumnSpec {
    int drums = 3;               ///< count ≥ 1
    double width = 0.3;          ///< side of the square section, m
    double drum_height = 0.5;    ///< height of each drum, m
    bool base = true;            ///< true: on a fixed 2 × 2 × 0.5 m slab `base`; false: D1 is fixed
};

/// append the column (base first, then D1 … DN); returns the index of D1
int add_column(Scene& scene, const ColumnSpec& column);

}  // namespace cairn
