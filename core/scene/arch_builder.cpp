#include "scene/arch_builder.hpp"

#include <cmath>
#include <utility>

#include "scene/scene_builder.hpp"
#include "scene/scene_toml.hpp"

namespace cairn {

namespace {

/// the world point at radius r and angle a from the left springing, at y
Vec3 ring_point(double r, double a, double y) { return {-r * std::cos(a), y, r * std::sin(a)}; }

/// abutment size (m) and centre under the springing on side s (−1 left, +1 right)
Vec3 abutment_size(const ArchSpec& arch) { return {std::max(1.0, 2.0 * arch.thickness), arch.depth + 0.5, 0.5}; }
Vec3 abutment_centre(const ArchSpec& arch, int side) { return {side * arch.radius, 0.0, -0.25}; }

/// angle of the left springing joint from the −x axis, rad
double springing_angle(const ArchSpec& arch) { return 0.5 * (M_PI - arch.angle); }

/// a segmental arch's fixed springer on side s (−1 left, +1 right): its top face is the springing
/// joint, its sides vertical, its bottom 0.5 m below the intrados springing point; hex8 order as a
/// voussoir's (corners 0-3 on the intrados side), so that the volume comes out positive
Corners springer(const ArchSpec& arch, int side) {
    const double a = springing_angle(arch), y = 0.5 * arch.depth;
    const double ri = arch.radius - 0.5 * arch.thickness, re = arch.radius + 0.5 * arch.thickness;
    const Vec3 pi = ring_point(ri, a, 0.0), pe = ring_point(re, a, 0.0);
    const double zb = pi.z() - 0.5;
    Corners c = {Vec3(pi.x(), -y, zb), Vec3(pi.x(), -y, pi.z()), Vec3(pi.x(), y, pi.z()), Vec3(pi.x(), y, zb),
                 Vec3(pe.x(), -y, zb), Vec3(pe.x(), -y, pe.z()), Vec3(pe.x(), y, pe.z()), Vec3(pe.x(), y, zb)};
    if (side > 0) {
        // mirror in x, then swap bottom and joint corners to keep the orientation
        for (Vec3& p : c) p.x() = -p.x();
        for (int k : {0, 2, 4, 6}) std::swap(c[size_t(k)], c[size_t(k + 1)]);
    }
    return c;
}

/// pointed arch: the intrados (r = R − t/2) or extrados point of joint k (0 … N, left to right) at y.
/// The left half is centred at x = c = pointed·2R with radius r + c, measured from the −x axis;
/// the right half is its mirror image
Vec3 pointed_joint(const ArchSpec& arch, int k, double r, double y) {
    const double c = arch.pointed * 2.0 * arch.radius;
    const int n = arch.voussoirs;
    const int side = 2 * k < n ? -1 : 1;
    const int from_left = side < 0 ? k : n - k;
    // the centreline reaches the axis x = 0 at the crown angle acos(c / (R + c))
    const double crown = std::acos(c / (arch.radius + c));
    // an even N's crown joint is vertical: each face point where its own circle meets x = 0
    const double a = 2 * k == n ? std::acos(c / (r + c)) : crown * 2.0 * from_left / n;
    return {side * ((r + c) * std::cos(a) - c), y, (r + c) * std::sin(a)};
}

}  // namespace

Corners arch_voussoir(const ArchSpec& arch, int i) {
    if (arch.pointed > 0.0) {
        const double ri = arch.radius - 0.5 * arch.thickness, re = arch.radius + 0.5 * arch.thickness;
        const double y = 0.5 * arch.depth;
        auto p = [&](int k, double r, double yy) { return pointed_joint(arch, k, r, yy); };
        return {p(i, ri, -y), p(i + 1, ri, -y), p(i + 1, ri, y), p(i, ri, y),
                p(i, re, -y), p(i + 1, re, -y), p(i + 1, re, y), p(i, re, y)};
    }
    const double s = springing_angle(arch);
    const double a0 = s + arch.angle * i / arch.voussoirs, a1 = s + arch.angle * (i + 1) / arch.voussoirs;
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
    if (arch.angle >= M_PI) {
        add_box(scene, "left", abutment_size(arch), abutment_centre(arch, -1), true);
        add_box(scene, "right", abutment_size(arch), abutment_centre(arch, +1), true);
        return first;
    }
    for (int side : {-1, 1}) {
        BlockDef b;
        b.name = side < 0 ? "left" : "right";
        b.shape = Shape::hexahedron;
        b.corners = springer(arch, side);
        b.fixed = true;
        scene.blocks.push_back(b);
    }
    return first;
}

std::string arch_blocks_toml(const ArchSpec& arch, const std::string& material) {
    Scene scene;
    add_arch(scene, arch);
    return blocks_toml(scene, material);
}

}  // namespace cairn
