#include "mesh.hpp"

#include <cmath>

namespace cairn::dem {

Vec3 Mesh::natural(int i, int j, int k) const {
    return Vec3(-1.0 + 2.0 * i / divisions[0], -1.0 + 2.0 * j / divisions[1], -1.0 + 2.0 * k / divisions[2]);
}

Mesh make_mesh(const Corners& corners, const std::array<int, 3>& div) {
    Mesh m;
    m.divisions = div;
    const int nx = div[0], ny = div[1], nz = div[2];
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) m.nodes.push_back(trilinear_point(corners, m.natural(i, j, k)));
    // node of element (i,j,k) at its local corner c
    auto corner_node = [&](int i, int j, int k, int c) {
        const auto& s = kCornerSigns[c];
        return m.node(i + (s[0] > 0), j + (s[1] > 0), k + (s[2] > 0));
    };
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                std::array<int, 8> e;
                for (int c = 0; c < 8; ++c) e[c] = corner_node(i, j, k, c);
                m.elements.push_back(e);
            }
    for (int s = 0; s < 6; ++s) {
        const auto& fc = kFaceCorners[s];
        // the block axis held fixed on this side, and the axes its first and second edges run along
        int fixed_axis = 0;
        for (int a = 0; a < 3; ++a)
            if (kCornerSigns[fc[0]][a] == kCornerSigns[fc[1]][a] && kCornerSigns[fc[0]][a] == kCornerSigns[fc[3]][a])
                fixed_axis = a;
        int u_axis = 0, v_axis = 0;
        for (int a = 0; a < 3; ++a) {
            if (kCornerSigns[fc[0]][a] != kCornerSigns[fc[1]][a]) u_axis = a;
            if (kCornerSigns[fc[0]][a] != kCornerSigns[fc[3]][a]) v_axis = a;
        }
        const int fixed_index = kCornerSigns[fc[0]][fixed_axis] > 0 ? div[fixed_axis] - 1 : 0;
        m.side_nu[s] = div[u_axis];
        m.side_nv[s] = div[v_axis];
        m.side_grid[s].assign(div[u_axis] * div[v_axis], -1);
        // corners of the side: the block corners on it, as mesh nodes
        for (int c = 0; c < 4; ++c) {
            const auto& sg = kCornerSigns[fc[c]];
            m.side_corners[s][c] = m.node(sg[0] > 0 ? nx : 0, sg[1] > 0 ? ny : 0, sg[2] > 0 ? nz : 0);
        }
        for (int v = 0; v < div[v_axis]; ++v)
            for (int u = 0; u < div[u_axis]; ++u) {
                std::array<int, 3> e{};
                e[fixed_axis] = fixed_index;
                // u and v count from the side's first corner, which may sit at the high end
                e[u_axis] = kCornerSigns[fc[0]][u_axis] > 0 ? div[u_axis] - 1 - u : u;
                e[v_axis] = kCornerSigns[fc[0]][v_axis] > 0 ? div[v_axis] - 1 - v : v;
                std::array<int, 4> face;
                for (int c = 0; c < 4; ++c) face[c] = corner_node(e[0], e[1], e[2], fc[c]);
                m.side_grid[s][v * div[u_axis] + u] = int(m.faces.size());
                m.faces.push_back(face);
                m.face_side.push_back(s);
            }
    }
    return m;
}

}  // namespace cairn::dem
