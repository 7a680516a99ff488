#pragma once
/// A colonnade: equal square columns in a row along x under one beam, on a fixed base slab (a
/// trilithon for two columns): for `cairn make colonnade` and tests. Shaken along x it rocks as
/// Makris & Vassiliou's frame (the ground_rocking reference, docs/validation.md).

#include "scene/scene.hpp"

namespace cairn {

/// the colonnade; columns C1 … CN from −x, the beam `beam`, the slab `base`
struct ColonnadeSpec {
    int columns = 2;             ///< count ≥ 2
    double width = 0.4;          ///< side of a column's square section, m
    double height = 1.6;         ///< column height, m
    double spacing = 1.2;        ///< centre to centre, m (≥ width)
    double beam_height = 0.4;    ///< m; the beam spans the outer columns' outer faces, as deep as a column
};

/// append the colonnade (base first, then C1 … CN and the beam); returns the index of C1
int add_colonnade(Scene& scene, const ColonnadeSpec& colonnade);

}  // namespace cairn
