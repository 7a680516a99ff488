#include "block_builder.hpp"

#include <cmath>

#include "dem/deformable/hex8.hpp"

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
