#include "engine_scenes.hpp"

#include <cmath>

#include "geometry/hexahedron.hpp"
#include "registry.hpp"
#include "scene/scene_builder.hpp"

namespace cairn::test {

Scene base_scene(const std::string& name) {
    Scene s;
    s.name = name;
    s.source = "<test>";
    s.materials.push_back({"stone", 2600.0, 30e9, 0.2});
    s.contact.kn = 3e7;
    s.contact.ks = 3e7;
    s.contact.friction = 0.6;
    s.run.dt = 1e-4;
    s.run.duration = 1.0;
    return s;
}

int add_hexahedron_box(Scene& scene, const std::string& name, const Vec3& size, const Vec3& centre,
                       bool fixed) {
    int i = cairn::add_box(scene, name, size, centre, fixed);
    scene.blocks[i].shape = Shape::hexahedron;
    // shift the corners so that the block frame origin is a corner, not the centre:
    // the backend must then find the centre of mass itself
    for (auto& c : scene.blocks[i].corners) c += 0.5 * size;
    scene.blocks[i].position = centre - 0.5 * size;
    return i;
}

Scene rocking_scene(double theta0) {
    Scene s = base_scene("rocking");
    s.contact.friction = 1.0;   // no sliding at the pivot
    add_box(s, "A", Vec3(0.2, 0.7, 1.0), Vec3::Zero(), false);
    add_box(s, "B", Vec3(1.0, 1.0, 0.5), Vec3(0, 0, -0.25), true);
    BlockDef& a = s.blocks[0];
    a.orientation = Quat(Eigen::AngleAxisd(theta0, Vec3::UnitY()));
    // pivot: block-frame point (0.1, 0, -0.5) placed at (0.1, 0, 0)
    Vec3 pivot_block(0.1, 0.0, -0.5);
    a.position = Vec3(0.1, 0.0, 0.0) - a.orientation * pivot_block;
    return s;
}

std::vector<std::string> engine_names() {
    std::vector<std::string> names;
    for (const auto& b : available_backends())
        if (b.name != "dem" && b.name != "double") names.push_back(b.name);   // not registry_test's double
    return names;
}

std::vector<std::string> all_backend_names() {
    std::vector<std::string> names;
    for (const auto& b : available_backends())
        if (b.name != "double") names.push_back(b.name);   // not registry_test's double
    return names;
}

std::unique_ptr<Backend> build_backend(const std::string& engine, const Scene& scene, const std::string& mode) {
    auto backend = make_backend(engine);
    RunOptions options;
    options.contact_mode = mode;
    backend->build(scene, options);
    return backend;
}

double angle_about_y(const Quat& q) {
    Mat3 r = q.toRotationMatrix();
    return std::atan2(r(0, 2), r(2, 2));
}

}  // namespace cairn::test
