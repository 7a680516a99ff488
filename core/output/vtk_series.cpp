#include "output/vtk_series.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "output/atomic_write.hpp"

namespace cairn {

namespace {

/// rotation angle of q relative to q0, rad in [0, π]
double angle_between(const Quat& q, const Quat& q0) {
    const Quat r = q * q0.conjugate();
    return 2.0 * std::atan2(r.vec().norm(), std::abs(r.w()));
}

/// per-cell or per-point field values of one block, appended `count` times
struct BlockFields {
    double id = 0.0;
    Vec3 v = Vec3::Zero(), omega = Vec3::Zero();
    double angle = 0.0;
};

void push3(std::vector<double>& out, const Vec3& v) { out.insert(out.end(), {v.x(), v.y(), v.z()}); }

}  // namespace

VtkGrid blocks_grid(const Scene& scene, const Sample& s, const Backend& backend) {
    VtkGrid g;
    g.cell_type = kVtkHexahedron;
    VtkField c_id{"block_id", 1, {}, true}, c_v{"velocity", 3, {}}, c_w{"angular_velocity", 3, {}},
        c_a{"rotation_angle", 1, {}};
    VtkField p_id{"block_id", 1, {}, true}, p_v{"velocity", 3, {}};
    auto add_cell = [&](const BlockFields& f) {
        c_id.values.push_back(f.id);
        push3(c_v.values, f.v);
        push3(c_w.values, f.omega);
        c_a.values.push_back(f.angle);
    };
    auto add_point = [&](const Vec3& p, const Vec3& v, double id) {
        g.points.push_back(p);
        push3(p_v.values, v);
        p_id.values.push_back(id);
    };
    size_t free_index = 0;
    for (size_t i = 0; i < scene.blocks.size(); ++i) {
        const BlockDef& def = scene.blocks[i];
        BlockFields f;
        f.id = double(i);
        const int base = int(g.points.size());
        if (def.fixed || free_index >= s.blocks.size()) {
            // fixed: the scene's pose, at rest
            for (const auto& c : def.corners) add_point(def.position + def.orientation * c, Vec3::Zero(), f.id);
            for (int k = 0; k < 8; ++k) g.connectivity.push_back(base + k);
            add_cell(f);
            if (!def.fixed) ++free_index;
            continue;
        }
        const BlockState& st = s.blocks[free_index++];
        f.v = st.velocity;
        f.omega = st.angular_velocity;
        f.angle = angle_between(st.orientation, def.orientation);
        const BlockMesh mesh = backend.block_mesh(int(i));
        if (!mesh.elements.empty()) {
            // deformable: the current nodes and their velocities, one cell per element
            for (size_t n = 0; n < mesh.nodes.size(); ++n)
                add_point(mesh.nodes[n], n < mesh.velocities.size() ? mesh.velocities[n] : st.velocity, f.id);
            for (const auto& e : mesh.elements) {
                for (int n : e) g.connectivity.push_back(base + n);
                add_cell(f);
            }
            continue;
        }
        // rigid: corners posed about the centre of mass (block frame → world), rigid-body velocity
        const Vec3 com = mass_properties(def.corners, 1.0).centre;
        for (const auto& c : def.corners) {
            const Vec3 p = st.position + st.orientation * (c - com);
            add_point(p, st.velocity + st.angular_velocity.cross(p - st.position), f.id);
        }
        for (int k = 0; k < 8; ++k) g.connectivity.push_back(base + k);
        add_cell(f);
    }
    g.cell_fields = {c_id, c_v, c_w, c_a};
    g.point_fields = {p_id, p_v};
    return g;
}

VtkGrid contacts_grid(const std::vector<ContactPoint>& contacts) {
    VtkGrid g;
    g.cell_type = kVtkVertex;
    VtkField n{"normal", 3, {}}, fn{"normal_force", 3, {}}, fs{"shear_force", 3, {}},
        a{"block_a", 1, {}, true}, b{"block_b", 1, {}, true};
    for (const auto& c : contacts) {
        g.connectivity.push_back(int(g.points.size()));
        g.points.push_back(c.position);
        push3(n.values, c.normal);
        push3(fn.values, c.normal_force);
        push3(fs.values, c.shear_force);
        a.values.push_back(c.block_a);
        b.values.push_back(c.block_b);
    }
    g.point_fields = {n, fn, fs, a, b};
    return g;
}

std::string safe_file_stem(const std::string& name) {
    std::string s;
    for (char c : name) {
        if (s.size() >= 64) break;
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                        c == '-' || c == '_';
        s += ok ? c : '_';
    }
    return s.empty() ? "scene" : s;
}

VtkSeries::VtkSeries(const Scene& scene, std::string dir)
    : scene_(scene), dir_(std::move(dir)), stem_(safe_file_stem(scene.name)) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec) throw Error("cannot create directory " + dir_ + ": " + ec.message());
}

void VtkSeries::add(const Sample& s, const Backend& backend) {
    char name[48];
    std::snprintf(name, sizeof name, "blocks_%06zu.vtu", blocks_.size());
    const VtkGrid blocks = blocks_grid(scene_, s, backend);
    write_file_atomic(dir_ + "/" + name, [&](std::ostream& out) { write_vtu(out, blocks); });
    blocks_.emplace_back(s.t, name);
    std::snprintf(name, sizeof name, "contacts_%06zu.vtu", contacts_.size());
    const VtkGrid contacts = contacts_grid(backend.contact_points());
    write_file_atomic(dir_ + "/" + name, [&](std::ostream& out) { write_vtu(out, contacts); });
    contacts_.emplace_back(s.t, name);
}

void VtkSeries::finish() {
    write_file_atomic(dir_ + "/" + stem_ + ".pvd", [&](std::ostream& out) { write_pvd(out, blocks_); });
    write_file_atomic(dir_ + "/" + stem_ + "_contacts.pvd",
                      [&](std::ostream& out) { write_pvd(out, contacts_); });
}

}  // namespace cairn
