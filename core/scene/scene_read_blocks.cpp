#include "scene/scene_read.hpp"

#include <cmath>

#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "scene/scene_limits.hpp"

namespace cairn::scene_detail {

namespace {

// a block or probe name becomes CSV column names (B.x, P.x): refuse what would break the header
void check_name(const TableReader& all, const std::string& name) {
    const std::string problem = column_name_problem(name);
    if (problem.empty()) return;
    Item(all.sources(), all.table().get(name), all.path_of(printable(name))).fail(problem);
}

// {axis = [..], angle = rad} or {quaternion = [w, x, y, z]}
Quat read_orientation(const Item& item) {
    TableReader o = item.reader({"axis", "angle", "quaternion"});
    Item axis = o.get("axis"), angle = o.get("angle"), quat = o.get("quaternion");
    if (quat) {
        if (axis || angle) item.fail("give either {axis, angle} or {quaternion}, not both");
        auto q = quat.numbers(4);
        double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        quat.check(std::abs(norm - 1.0) <= 1e-6, "a rotation quaternion must have norm 1 (within 1e-6)");
        return Quat(q[0], q[1], q[2], q[3]).normalized();
    }
    if (!axis || !angle) item.fail("needs {axis = [x, y, z], angle = rad} or {quaternion = [w, x, y, z]}");
    Vec3 a = axis.vec3();
    axis.check(a.norm() > 0.0, "the rotation axis must not be zero");
    return Quat(Eigen::AngleAxisd(angle.number(), a.normalized()));
}

Corners read_corners(const Item& item) {
    const std::string what = "expected an array of 8 corners [x, y, z]";
    item.check(item.node().is_array() && item.array().size() == 8, what);
    Corners c;
    for (std::size_t i = 0; i < 8; ++i) c[i] = item.element(i).vec3();
    std::string problem = convexity_problem(c);
    item.check(problem.empty(), "not a valid convex hexahedron: " + problem);
    return c;
}

MeshDef read_mesh(const Item& item) {
    TableReader m = item.reader({"divisions", "mass", "fix_base", "fixed_nodes"});
    MeshDef mesh;
    if (Item it = m.get("divisions")) {
        auto a = it.integers();
        it.check(a.size() == 3, "expected an array of 3 integers [nx, ny, nz]");
        for (int k = 0; k < 3; ++k) {
            it.check(a[k] >= 1 && a[k] <= 1000000, "every division must be an integer >= 1");
            mesh.divisions[k] = static_cast<int>(a[k]);
        }
    }
    if (Item it = m.get("mass")) {
        std::string s = it.string();
        if (s == "lumped") mesh.mass = MassScheme::lumped;
        else if (s == "consistent") mesh.mass = MassScheme::consistent;
        else if (s == "barycentre") mesh.mass = MassScheme::barycentre;
        else if (s == "corrected") mesh.mass = MassScheme::corrected;
        else it.fail("expected \"lumped\", \"consistent\", \"barycentre\" or \"corrected\"");
    }
    if (Item it = m.get("fix_base")) mesh.fix_base = it.boolean();
    if (Item it = m.get("fixed_nodes")) {
        long long last = 1;
        for (int d : mesh.divisions) last *= (d + 1);
        last -= 1;
        for (long long n : it.integers()) {
            it.check(n >= 0 && n <= last, "node " + std::to_string(n) + " is outside 0.." +
                                              std::to_string(last) + " for this mesh");
            mesh.fixed_nodes.push_back(static_cast<int>(n));
        }
    }
    return mesh;
}

BlockDef read_block(const TableReader& all, const std::string& name, const Scene& scene) {
    check_name(all, name);
    TableReader b = sub_table(all, name, {"shape", "size", "corners", "position", "orientation",
                                          "pivot", "velocity", "angular_velocity", "material",
                                          "fixed", "model", "mesh"});
    BlockDef def;
    def.name = name;
    Item size = b.get("size"), corners = b.get("corners");
    std::string shape = "box";
    if (Item it = b.get("shape")) {
        shape = it.string();
        it.check(shape == "box" || shape == "hexahedron", "expected \"box\" or \"hexahedron\"");
    }
    if (shape == "box") {
        if (corners) corners.fail("a box is given by size; corners are for shape = \"hexahedron\"");
        Item s = b.require("size");
        def.size = s.vec3();
        s.check((def.size.array() > 0.0).all(), "every edge length must be > 0");
        def.corners = box_corners(def.size);
    } else {
        def.shape = Shape::hexahedron;
        if (size) size.fail("a hexahedron is given by corners; size is for shape = \"box\"");
        def.corners = read_corners(b.require("corners"));
    }
    if (Item it = b.get("position")) def.position = it.vec3();
    if (Item it = b.get("orientation")) def.orientation = read_orientation(it);
    if (Item it = b.get("pivot")) {
        // placed at position, then rotated about the pivot: fold into the position
        Vec3 pivot = it.vec3();
        def.position = pivot + def.orientation * (def.position - pivot);
    }
    if (Item it = b.get("velocity")) def.velocity = it.vec3();
    if (Item it = b.get("angular_velocity")) def.angular_velocity = it.vec3();
    Item mat = b.require("material");
    std::string mat_name = mat.string();
    def.material = -1;
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == mat_name) def.material = static_cast<int>(i);
    mat.check(def.material >= 0, "no material of that name in [materials]");
    if (Item it = b.get("fixed")) def.fixed = it.boolean();
    if (Item it = b.get("model")) {
        std::string m = it.string();
        if (m == "rigid") def.model = BlockModel::rigid;
        else if (m == "deformable") def.model = BlockModel::deformable;
        else it.fail("expected \"rigid\" or \"deformable\"");
    }
    if (Item it = b.get("mesh")) def.mesh = read_mesh(it);
    return def;
}

// a point of block `b` given as `point` (block frame) or `corner` (0..7)
Vec3 read_point(const Item& point, const Item& corner, const BlockDef& b) {
    if (corner) {
        long long i = corner.integer();
        corner.check(i >= 0 && i <= 7, "a corner index must be 0..7");
        return b.corners[static_cast<std::size_t>(i)];
    }
    return point.vec3();
}

}  // namespace

void read_blocks(const TableReader& root, Scene& scene) {
    Item section = root.require("blocks");
    TableReader all(root.sources(), section.table(), "blocks");
    section.check(!all.table().empty(), "needs at least one block");
    bool any_free = false;
    for (auto&& [k, v] : all.table()) {
        scene.blocks.push_back(read_block(all, std::string(k.str()), scene));
        any_free = any_free || !scene.blocks.back().fixed;
    }
    section.check(any_free, "at least one block must be free (fixed = false)");
}

void read_loads(const TableReader& root, Scene& scene) {
    Item section = root.get("loads");
    if (!section) return;
    TableReader all(root.sources(), section.table(), "loads");
    for (auto&& [k, v] : all.table()) {
        TableReader l = sub_table(all, std::string(k.str()),
                                  {"block", "force", "point", "corner", "ramp", "start"});
        LoadDef load;
        Item block = l.require("block");
        load.block = block_named(block, scene);
        const BlockDef& b = scene.blocks[static_cast<std::size_t>(load.block)];
        block.check(!b.fixed, "a load needs a free block; this one is fixed");
        load.force = l.require("force").vec3();
        Item point = l.get("point"), corner = l.get("corner");
        if (point && corner) corner.fail("give point or corner, not both");
        if (point && point.node().is_string()) {
            point.check(point.string() == "centre", "expected [x, y, z] (block frame, m) or \"centre\"");
            point = Item(point.sources(), nullptr, point.key());
        }
        if (point || corner) {
            load.point = read_point(point, corner, b);
        } else {
            double density = scene.materials[static_cast<std::size_t>(b.material)].density;
            load.point = mass_properties(b.corners, density).centre;
        }
        if (Item it = l.get("ramp")) {
            load.ramp = it.number();
            it.check(load.ramp >= 0.0, "must be >= 0");
        }
        if (Item it = l.get("start")) {
            load.start = it.number();
            it.check(load.start >= 0.0, "must be >= 0");
        }
        scene.loads.push_back(load);
    }
}

void read_probes(const TableReader& root, Scene& scene) {
    Item section = root.get("probes");
    if (!section) return;
    TableReader all(root.sources(), section.table(), "probes");
    for (auto&& [k, v] : all.table()) {
        check_name(all, std::string(k.str()));
        TableReader p = sub_table(all, std::string(k.str()), {"block", "point", "corner"});
        ProbeDef probe;
        probe.name = std::string(k.str());
        probe.block = block_named(p.require("block"), scene);
        Item point = p.get("point"), corner = p.get("corner");
        if (point && corner) corner.fail("give point or corner, not both");
        if (!point && !corner) p.require("point");   // reports the missing key
        probe.point = read_point(point, corner, scene.blocks[static_cast<std::size_t>(probe.block)]);
        scene.probes.push_back(probe);
    }
}

}  // namespace cairn::scene_detail
