#include "scene/arch_builder.hpp"

#include <cmath>
#include <cstdio>

#include "scene/scene_builder.hpp"

namespace cairn {

namespace {

/// the world point at radius r and angle a from the left springing, at y
Vec3 ring_point(double r, double a, double y) { return {-r * std::cos(a), y, r * std::sin(a)}; }

/// abutment size (m) and centre under the springing on side s (−1 left, +1 right)
Vec3 abutment_size(const ArchSpec& arch) { return {std::max(1.0, 2.0 * arch.thickness), arch.depth + 0.5, 0.5}; }
Vec3 abutment_centre(const ArchSpec& arch, int side) { return {side * arch.radius, 0.0, -0.25}; }

}  // namespace

Corners arch_voussoir(const ArchSpec& arch, int i) {
    const double a0 = M_PI * i / arch.voussoirs, a1 = M_PI * (i + 1) / arch.voussoirs;
    const double ri = arch.radius - 0.5 * arch.thickness, re = arch.radius + 0.5 * arch.thickness;
    const double y = 0.5 * arch.depth;
    return {ring_point(ri, a0, -y), ring_point(ri, a1, -y), ring_point(ri, a1, y), ring_point(ri, a0, y),
            ring_point(re, a0, -y), ring_point(re, a1, -y), ring_point(re, a1, y), ring_point(re, a0, y)};
}

int add_arch(Scene& scene, const ArchSpec& arch) {
    const int first = int(scene.blocks.size());
    for (int i = 0; i < arch.voussoirs; ++i) {
        BlockDef b;
        b.name = "V" + std::to_string(i + 1);
        b.shape = Shape::hexahedron;
        b.corners = arch_voussoir(arch, i);
        scene.blocks.push_back(b);
    }
    add_box(scene, "left", abutment_size(arch), abutment_centre(arch, -1), true);
    add_box(scene, "right", abutment_size(arch), abutment_centre(arch, +1), true);
    return first;
}

std::string arch_blocks_toml(const ArchSpec& arch, const std::string& material) {
    std::string out;
    char buf[160];
    for (int i = 0; i < arch.voussoirs; ++i) {
        out += "[blocks.V" + std::to_string(i + 1) + "]\nshape = \"hexahedron\"\ncorners = [\n";
        for (const Vec3& c : arch_voussoir(arch, i)) {
            std::snprintf(buf, sizeof buf, "  [%.9f, %.9f, %.9f],\n", c.x(), c.y(), c.z());
            out += buf;
        }
        out += "]\nmaterial = \"" + material + "\"\n\n";
    }
    for (int side : {-1, 1}) {
        const Vec3 s = abutment_size(arch), c = abutment_centre(arch, side);
        std::snprintf(buf, sizeof buf,
                      "[blocks.%s]\nsize = [%.3f, %.3f, %.3f]      # m\nposition = [%.9f, %.3f, %.3f]\nmaterial = \"%s\"\nfixed = true\n\n",
                      side < 0 ? "left" : "right", s.x(), s.y(), s.z(), c.x(), c.y(), c.z(), material.c_str());
        out += buf;
    }
    return out;
}

}  // namespace cairn
