#include "block_builder.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>

#include "contact.hpp"
#include "dem/deformable/hex8.hpp"
#include "error.hpp"
#include "run/run_limits.hpp"

namespace cairn::dem {

namespace {

// hitting points of every boundary face. On a side meshed into equal faces a point on an edge
// shared by two faces (or a vertex shared by four) is kept once, by the face before it, with the
// tributary areas of all the faces that share it: the side carries one regular grid.
std::vector<std::vector<HitPoint>> hitting_points(const Mesh& mesh, double spacing) {
    auto quad = [&](int f) {
        const auto& fc = mesh.faces[f];
        return Quad{mesh.nodes[fc[0]], mesh.nodes[fc[1]], mesh.nodes[fc[2]], mesh.nodes[fc[3]]};
    };
    std::vector<std::vector<HitPoint>> hits(mesh.faces.size());
    for (size_t f = 0; f < mesh.faces.size(); ++f) hits[f] = hit_grid(quad(int(f)), spacing);
    for (int s = 0; s < 6; ++s) {
        const auto& grid = mesh.side_grid[s];
        const int nu = mesh.side_nu[s], nv = mesh.side_nv[s];
        if (grid.size() < 2) continue;
        // only where every face of the side is the same: the shared points then coincide exactly
        const auto counts = hit_grid_counts(quad(grid[0]), spacing);
        const double area = quad_area(quad(grid[0]));
        bool uniform = true;
        for (int f : grid)
            uniform = uniform && hit_grid_counts(quad(f), spacing) == counts &&
                      std::abs(quad_area(quad(f)) - area) <= 1e-12 * area;
        if (!uniform) continue;
        const int gi = counts[0], gj = counts[1];
        for (int v = 0; v < nv; ++v)
            for (int u = 0; u < nu; ++u) {
                std::vector<HitPoint> kept;
                const auto& all = hits[grid[v * nu + u]];
                for (int j = 0; j < gj; ++j)
                    for (int i = 0; i < gi; ++i) {
                        if ((i == gi - 1 && u < nu - 1) || (j == gj - 1 && v < nv - 1)) continue;
                        HitPoint p = all[j * gi + i];
                        p.area *= (i == 0 && u > 0 ? 2 : 1) * (j == 0 && v > 0 ? 2 : 1);
                        kept.push_back(p);
                    }
                hits[grid[v * nu + u]] = std::move(kept);
            }
    }
    return hits;
}

// bytes per mesh node: reference, current and rest positions, velocity, force, acceleration,
// mass-weighted offset (24 B each), lumped mass, fixed flags, incidence and gather indices
constexpr double kNodeBytes = 220;
// bytes per element: node lists (mesh, body, batch), batched element forces (192), incidence (64),
// build-time corners and centroids, and the consistent-mass triplets assembled for every scheme
// (64 of 16 B, up to twice that while the vector grows)
constexpr double kElementBytes = 2700;
// per element with a general (not parallelepiped) shape: Jacobians at 8 Gauss points, and a
// cached element frequency
constexpr double kGeneralElementBytes = 800;
// consistent mass on top: the reduced triplets, the sparse matrix, per node
constexpr double kConsistentElementBytes = 2100;
// the Cholesky factor of the consistent mass: fill-in grows like nodes^(4/3) for a 3-D mesh; the
// factor is fitted to a 30x30x30 block (peak resident memory 296 MB, estimate 313 MiB; lumped
// 58 MB against an estimate of 78 MiB)
constexpr double kConsistentFillBytes = 192.0;
// bytes per hitting point: the point (24), its stick anchor with the last evaluation's track
// (sizeof(Anchor), 160 on x86-64), a pending point force (48)
constexpr double kHitBytes = 24 + double(sizeof(Anchor)) + 48;
// bytes per point of a side's grid built once for the critical step
constexpr double kSideGridBytes = 24;
// bytes per boundary face: its nodes, side and grid slot
constexpr double kFaceBytes = 24;

// points of hit_grid on a face with edges of these lengths, in double
double grid_points(double len_u, double len_v, double spacing) {
    auto count = [&](double len) { return std::max(2.0, std::ceil(len / spacing - 1e-9) + 1.0); };
    return count(len_u) * count(len_v);
}

std::string g(double x) { return message_number(x, 3); }

}  // namespace

BuildEstimate estimate_build(const Scene& scene) {
    BuildEstimate est;
    const double spacing = scene.contact.grid_spacing;
    double largest = -1.0;
    for (size_t bi = 0; bi < scene.blocks.size(); ++bi) {
        const BlockDef& def = scene.blocks[bi];
        const bool deformable = def.model == BlockModel::deformable && !def.fixed;
        double d[3] = {1.0, 1.0, 1.0};
        if (deformable)
            for (int k = 0; k < 3; ++k) d[k] = double(def.mesh.divisions[k]);
        const double nodes = (d[0] + 1) * (d[1] + 1) * (d[2] + 1), elements = d[0] * d[1] * d[2];
        double mesh = nodes * kNodeBytes + elements * kElementBytes;
        if (deformable && def.shape == Shape::hexahedron) mesh += elements * kGeneralElementBytes;
        if (deformable && def.mesh.mass == MassScheme::consistent)
            mesh += elements * kConsistentElementBytes + std::pow(nodes, 4.0 / 3.0) * kConsistentFillBytes;
        double hits = 0.0;
        for (int s = 0; s < 6; ++s) {
            const auto& fc = kFaceCorners[s];
            const auto& c = def.corners;
            const double len_u = std::max((c[fc[1]] - c[fc[0]]).norm(), (c[fc[2]] - c[fc[3]]).norm());
            const double len_v = std::max((c[fc[3]] - c[fc[0]]).norm(), (c[fc[2]] - c[fc[1]]).norm());
            // the side's axes: divisions along its first and second edges
            int u_axis = 0, v_axis = 0;
            for (int a = 0; a < 3; ++a) {
                if (kCornerSigns[fc[0]][a] != kCornerSigns[fc[1]][a]) u_axis = a;
                if (kCornerSigns[fc[0]][a] != kCornerSigns[fc[3]][a]) v_axis = a;
            }
            const double faces = d[u_axis] * d[v_axis];
            const double per_face = grid_points(len_u / d[u_axis], len_v / d[v_axis], spacing);
            const double side = def.fixed ? 0.0 : grid_points(len_u, len_v, spacing);
            hits += faces * per_face;
            mesh += faces * kFaceBytes;
            est.hit_bytes += side * kSideGridBytes;
            est.largest_grid = std::max({est.largest_grid, per_face, side});
        }
        est.nodes += nodes;
        est.elements += elements;
        est.hit_points += hits;
        est.mesh_bytes += mesh;
        est.hit_bytes += hits * kHitBytes;
        if (mesh > largest) largest = mesh, est.largest_mesh = int(bi);
    }
    return est;
}

void check_build_size(const Scene& scene, const RunLimits& limits) {
    const BuildEstimate est = estimate_build(scene);
    const double budget = memory_budget(limits);
    const std::string spacing = "contact.grid_spacing = " + g(scene.contact.grid_spacing);
    std::string mesh_key;
    if (est.largest_mesh >= 0) {
        const BlockDef& b = scene.blocks[size_t(est.largest_mesh)];
        const auto& d = b.mesh.divisions;
        mesh_key = "blocks." + b.name + ".mesh.divisions = [" + std::to_string(d[0]) + ", " +
                   std::to_string(d[1]) + ", " + std::to_string(d[2]) + "]";
    }
    const bool hits_dominate = est.hit_bytes >= est.mesh_bytes;
    const std::string key = scene.source + ": " + (hits_dominate ? spacing : mesh_key) + ": ";
    // the engine indexes nodes, element incidences and a face's points with 32-bit integers
    for (const auto& b : scene.blocks) {
        if (b.model != BlockModel::deformable || b.fixed) continue;
        const auto& d = b.mesh.divisions;
        const double nodes = double(d[0] + 1) * double(d[1] + 1) * double(d[2] + 1);
        const double elements = double(d[0]) * double(d[1]) * double(d[2]);
        if (nodes > INT_MAX || 8.0 * elements > INT_MAX)
            throw Error(scene.source + ": blocks." + b.name + ".mesh.divisions = [" + std::to_string(d[0]) + ", " +
                        std::to_string(d[1]) + ", " + std::to_string(d[2]) + "]: " + g(elements) +
                        " elements and " + g(nodes) + " nodes, beyond the engine's 32-bit indices (at most " +
                        g(INT_MAX / 8.0) + " elements)");
    }
    if (est.largest_grid > INT_MAX / 2)
        throw Error(scene.source + ": " + spacing + ": " + g(est.largest_grid) +
                    " hitting points on one face, beyond the engine's 32-bit indices");
    if (est.hit_points > kMaxHitPoints && !limits.allow_large)
        throw Error(scene.source + ": " + spacing + ": " + g(est.hit_points) +
                    " hitting points on the block faces, beyond the limit of " + g(kMaxHitPoints) +
                    " (--allow-large lifts it: every step visits each point, 1e6 points take about 0.05 s a step)");
    if (est.bytes() > budget)
        throw Error(key + "the model would take about " + bytes_text(est.bytes()) + " (" + g(est.elements) +
                    " elements, " + g(est.nodes) + " nodes, " + g(est.hit_points) +
                    " hitting points), beyond the memory budget of " + bytes_text(budget) +
                    " (default half of the machine's memory; --memory-budget changes it)");
}

namespace {
// every side planar and square to each side it shares an edge with, to rounding (1e-12)
bool is_box(const std::array<Vec3, 8>& corners) {
    std::array<Vec3, 6> normal;
    for (int s = 0; s < 6; ++s) {
        const auto& fc = kFaceCorners[s];
        const Quad q{corners[fc[0]], corners[fc[1]], corners[fc[2]], corners[fc[3]]};
        normal[s] = quad_centre_normal(q);
        const Vec3 centre = 0.25 * (q[0] + q[1] + q[2] + q[3]);
        const double size = (q[2] - q[0]).norm();
        for (const auto& p : q)
            if (std::abs(normal[s].dot(p - centre)) > 1e-12 * size) return false;
    }
    for (int s = 0; s < 6; ++s)
        for (int o = s + 1; o < 6; ++o) {
            int shared = 0;
            for (int i : kFaceCorners[s])
                for (int j : kFaceCorners[o]) shared += i == j;
            if (shared == 2 && std::abs(normal[s].dot(normal[o])) > 1e-12) return false;
        }
    return true;
}
}  // namespace

Block make_block(const BlockDef& def, const Scene& scene) {
    const Material& mat = scene.materials[def.material];
    const bool deformable = def.model == BlockModel::deformable && !def.fixed;
    Block b;
    b.name = def.name;
    b.fixed = def.fixed;
    MassProperties mp = mass_properties(def.corners, mat.density);
    b.volume = mp.volume;
    b.com_in_frame = mp.centre;
    b.mesh = make_mesh(def.corners, deformable ? def.mesh.divisions : std::array<int, 3>{1, 1, 1});
    b.body.q = def.orientation.normalized();
    b.body.x = def.position + b.body.q * mp.centre;
    b.body.mass = mp.mass;
    b.body.inertia_body = mp.inertia;
    for (const auto& c : def.corners) b.r_max = std::max(b.r_max, (c - mp.centre).norm());
    b.min_edge = 1e300;
    for (int s = 0; s < 6; ++s) {
        const auto& fc = kFaceCorners[s];
        Quad q{def.corners[fc[0]], def.corners[fc[1]], def.corners[fc[2]], def.corners[fc[3]]};
        b.side_area[s] = quad_area(q);
        for (int i = 0; i < 4; ++i) b.min_edge = std::min(b.min_edge, (q[(i + 1) % 4] - q[i]).norm());
    }
    b.box = !deformable && is_box(def.corners);
    // hitting points: the paper's scheme only (the overlap scheme cuts the faces as it goes)
    if (scene.contact.scheme == ContactScheme::paper) b.hits = hitting_points(b.mesh, scene.contact.grid_spacing);
    else b.hits.assign(b.mesh.faces.size(), {});
    const size_t nn = b.mesh.nodes.size();
    b.x.resize(nn);
    b.v.assign(nn, Vec3::Zero());
    b.f.assign(nn, Vec3::Zero());
    if (deformable) {
        std::vector<char> fixed(nn, 0);
        for (int n : def.mesh.fixed_nodes) fixed[n] = 1;
        if (def.mesh.fix_base)
            for (int j = 0; j <= def.mesh.divisions[1]; ++j)
                for (int i = 0; i <= def.mesh.divisions[0]; ++i) fixed[b.mesh.node(i, j, 0)] = 1;
        b.deformable = std::make_shared<DeformableBody>(b.mesh, mat, def.mesh.mass, scene.damping.beta, fixed);
        b.body.mass = b.deformable->mass();
        b.body.inertia_body = b.deformable->inertia();
        for (size_t n = 0; n < nn; ++n) {
            Vec3 r = b.body.q * (b.mesh.nodes[n] - mp.centre);
            b.x[n] = b.body.x + r;
            b.v[n] = fixed[n] ? Vec3::Zero() : Vec3(def.velocity + def.angular_velocity.cross(r));
        }
    } else {
        for (const auto& p : b.mesh.nodes) b.local.push_back(p - mp.centre);
        for (int s = 0; s < 6; ++s) {
            const auto& c = b.mesh.side_corners[size_t(s)];
            const Quad q{b.local[size_t(c[0])], b.local[size_t(c[1])], b.local[size_t(c[2])], b.local[size_t(c[3])]};
            b.side_normal_local[size_t(s)] = quad_centre_normal(q);
            b.side_centre_local[size_t(s)] = 0.25 * (q[0] + q[1] + q[2] + q[3]);
        }
        if (!def.fixed) {
            b.body.v = def.velocity;
            b.body.set_omega(def.angular_velocity);
        }
    }
    b.body.inv_inertia_body = b.body.inertia_body.inverse();
    b.update_nodes();
    b.x_at_refresh = b.body.x;
    b.q_at_refresh = b.body.q;
    return b;
}

MaterialPoint locate(const Block& b, int block_index, const Vec3& frame_point) {
    MaterialPoint p;
    p.block = block_index;
    p.frame = frame_point;
    // Newton inversion of each element's trilinear map; keep the element whose natural
    // coordinates lie inside (or least outside) [-1, 1]³. The map is affine for the
    // parallelepipeds of box meshes, so a point outside a block still lands exactly.
    double best = 1e300;
    for (size_t e = 0; e < b.mesh.elements.size(); ++e) {
        Corners c;
        for (int a = 0; a < 8; ++a) c[a] = b.mesh.nodes[b.mesh.elements[e][a]];
        Vec3 xi = Vec3::Zero();
        for (int it = 0; it < 20; ++it) {
            Mat83 dn = hex8_dshape(xi);
            Mat3 j = Mat3::Zero();
            for (int a = 0; a < 8; ++a) j += c[a] * dn.row(a);
            Vec3 step = j.lu().solve(frame_point - trilinear_point(c, xi));
            xi += step;
            if (step.norm() < 1e-14) break;
        }
        double outside = (xi.cwiseAbs().array() - 1.0).max(0.0).maxCoeff();
        if (outside < best) best = outside, p.element = int(e), p.xi = xi;
    }
    return p;
}

Vec3 world_position(const Block& b, const MaterialPoint& p) {
    // the nodes move rigidly or deform; either way the point follows the shape functions
    auto n = hex8_shape(p.xi);
    Vec3 x = Vec3::Zero();
    for (int a = 0; a < 8; ++a) x += n[a] * b.x[b.mesh.elements[p.element][a]];
    return x;
}

void add_point_force(Block& b, const MaterialPoint& p, const Vec3& force) {
    auto n = hex8_shape(p.xi);
    for (int a = 0; a < 8; ++a) b.f[b.mesh.elements[p.element][a]] += n[a] * force;
}

}  // namespace cairn::dem
