#pragma once
/// A block's hexahedral mesh: its 8 corners subdivided trilinearly into nx × ny × nz hex8
/// elements. Node (i, j, k) has index i + (nx+1)·(j + (ny+1)·k) (docs/scenes.md). The boundary is
/// kept as 6 sides (the block's faces, numbered as kFaceCorners), each a grid of element faces.

#include <array>
#include <vector>

#include "geometry/hexahedron.hpp"

namespace cairn::dem {

struct Mesh {
    std::array<int, 3> divisions{1, 1, 1};          ///< elements along ξ, η, ζ
    std::vector<Vec3> nodes;                        ///< reference positions, block frame, m
    std::vector<std::array<int, 8>> elements;       ///< node indices in hex8 corner order
    std::vector<std::array<int, 4>> faces;          ///< boundary faces, outward order
    std::vector<int> face_side;                     ///< side (0-5) of each boundary face
    std::array<std::array<int, 4>, 6> side_corners; ///< node indices of each side's 4 corners
    std::array<int, 6> side_nu{}, side_nv{};        ///< faces along a side's first and second direction
    std::array<std::vector<int>, 6> side_grid;      ///< face index at [v·nu + u] of each side

    /// node index of grid point (i, j, k)
    int node(int i, int j, int k) const { return i + (divisions[0] + 1) * (j + (divisions[1] + 1) * k); }
    /// natural coordinates of node (i, j, k) in the block
    Vec3 natural(int i, int j, int k) const;
};

/// mesh the hexahedron with the given element counts (each ≥ 1)
Mesh make_mesh(const Corners& corners, const std::array<int, 3>& divisions);

}  // namespace cairn::dem
