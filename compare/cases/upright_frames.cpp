#include "cases/upright_frames.hpp"

#include <cmath>

#include "cases/case_util.hpp"

namespace cairn::cases {

namespace {

/// index of the written axis that the turn p makes the new axis m
int old_axis(const Mat3& p, int m) {
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(p(i, m)) > std::abs(p(k, m))) k = i;
    return k;
}

/// the rotation whose new z is s·e_k of the written frame: new x, y, z = e_i, s·e_j, s·e_k with
/// (i, j, k) cyclic, a proper rotation
Mat3 turn_to(int k, double s) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    Mat3 p = Mat3::Zero();
    p(i, 0) = 1.0;
    p(j, 1) = s;
    p(k, 2) = s;
    return p;
}

/// a fixed box's side that block `on` rests on: of the sides whose plane the centre of `on` lies
/// beyond, the one facing most against gravity (a slab's top under a lintel it carries, a slope's
/// face at any angle); +z kept on a tie within 1e-9, and where no side qualifies
Mat3 facing_turn(const BlockDef& base, const BlockDef& on, const Vec3& up) {
    Vec3 c = Vec3::Zero();
    for (const auto& x : on.corners) c += x / 8.0;
    const Vec3 local = base.orientation.conjugate() * (on.position + on.orientation * c - base.position);
    const Vec3 half = 0.5 * base.size, up_local = base.orientation.conjugate() * up;
    int k = 2;
    double s = 1.0, best = local.z() > half.z() ? up_local.z() : -2.0;
    for (int i = 0; i < 3; ++i)
        for (double sign : {1.0, -1.0})
            if (sign * local[i] > half[i] && sign * up_local[i] > best + 1e-9) {
                best = sign * up_local[i];
                k = i;
                s = sign;
            }
    return turn_to(k, s);
}

/// the turn of a fixed box: its side the reference block rests on (without one, its axis nearest up)
Mat3 fixed_turn(const Scene& scene, const BlockDef& d) {
    if (scene.reference && !scene.blocks.at(size_t(scene.reference->block)).fixed)
        return facing_turn(d, scene.blocks.at(size_t(scene.reference->block)), up_direction(scene));
    return upright_turn(d, up_direction(scene));
}

/// "up" for the free blocks: the top of the first fixed block (the kinds' base, a slope's normal),
/// or against gravity where that is not a box
Vec3 base_up(const Scene& scene) {
    for (const auto& d : scene.blocks)
        if (d.fixed) {
            if (d.shape != Shape::box) break;
            return d.orientation * (fixed_turn(scene, d) * Vec3::UnitZ());
        }
    return up_direction(scene);
}

/// each block's turn: a fixed box by fixed_turn, a free box by its axis nearest the base's up; a
/// general hexahedron as written (identity)
std::vector<Mat3> block_turns(const Scene& scene) {
    const Vec3 up = base_up(scene);
    std::vector<Mat3> out;
    for (const auto& d : scene.blocks)
        out.push_back(d.shape != Shape::box ? Mat3::Identity() : d.fixed ? fixed_turn(scene, d) : upright_turn(d, up));
    return out;
}

/// divisions along the written axes, renamed as the turn p renames the axes
std::array<int, 3> renamed(const std::array<int, 3>& divisions, const Mat3& p) {
    std::array<int, 3> out{};
    for (int m = 0; m < 3; ++m) out[size_t(m)] = divisions[size_t(old_axis(p, m))];
    return out;
}

}  // namespace

Mat3 upright_turn(const BlockDef& b, const Vec3& up) {
    const Mat3 r = b.orientation.toRotationMatrix();
    int k = 2;
    for (int i = 0; i < 2; ++i)
        if (std::abs(r.col(i).dot(up)) > std::abs(r.col(k).dot(up)) + 1e-9) k = i;
    return turn_to(k, r.col(k).dot(up) < 0.0 ? -1.0 : 1.0);
}

Scene upright_frames(const Scene& scene) {
    Scene out = scene;
    const std::vector<Mat3> turns = block_turns(scene);
    for (size_t b = 0; b < out.blocks.size(); ++b) {
        const Mat3& p = turns[b];
        if (p.isIdentity(0.0)) continue;
        BlockDef& d = out.blocks[b];
        for (auto& c : d.corners) c = p.transpose() * c;
        d.size = (p.transpose() * d.size).cwiseAbs();
        d.orientation = (d.orientation * Quat(p)).normalized();
        d.mesh.divisions = renamed(d.mesh.divisions, p);
        for (auto& l : out.loads)
            if (l.block == int(b)) l.point = p.transpose() * l.point;
        for (auto& pr : out.probes)
            if (pr.block == int(b)) pr.point = p.transpose() * pr.point;
    }
    return out;
}

std::vector<Sample> upright_samples(const Scene& scene, const std::vector<Sample>& samples) {
    const std::vector<Mat3> all = block_turns(scene);
    std::vector<Quat> turns;
    bool any = false;
    for (size_t b = 0; b < scene.blocks.size(); ++b)
        if (!scene.blocks[b].fixed) {
            any = any || !all[b].isIdentity(0.0);
            turns.push_back(Quat(all[b]));
        }
    if (!any) return samples;
    std::vector<Sample> out = samples;
    for (auto& s : out)
        for (size_t i = 0; i < s.blocks.size() && i < turns.size(); ++i)
            s.blocks[i].orientation = (s.blocks[i].orientation * turns[i]).normalized();
    return out;
}

std::array<int, 3> upright_divisions(const Scene& scene, int b, const std::array<int, 3>& divisions) {
    return renamed(divisions, block_turns(scene).at(size_t(b)));
}

}  // namespace cairn::cases
