#include "engine_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "registry.hpp"
#include "scene/scene_builder.hpp"

namespace cairn::test {

Scene base_scene(const std::string& name) {
    Scene s = stone_scene(0.6);
    s.name = name;
    s.run.dt = 1e-4;
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

std::vector<std::string> engine_names() {
    std::vector<std::string> names;
    for (const auto& b : available_backends())
        if (b.name != "dem" && b.name != "double") names.push_back(b.name);   // not registry_test's double
    return names;
}

std::string shipped_scene_text(const std::string& relative) {
    std::ifstream in(std::string(CAIRN_SOURCE_DIR) + "/scenarios/" + relative);
    REQUIRE(in.good());
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> all_backend_names() {
    std::vector<std::string> names;
    for (const auto& b : available_backends())
        if (b.name != "double") names.push_back(b.name);   // not registry_test's double
    return names;
}

bool has_matched_mode(const std::string& engine) {
    for (const auto& b : available_backends())
        if (b.name == engine)
            for (const auto& f : b.capabilities)
                if (f.feature == Feature::penalty_stiffness) return f.support != Support::none;
    return true;
}

std::vector<std::string> matched_backend_names() {
    std::vector<std::string> names;
    for (const auto& name : all_backend_names())
        if (has_matched_mode(name)) names.push_back(name);
    return names;
}

std::unique_ptr<Backend> build_backend(const std::string& engine, const Scene& scene, const std::string& mode) {
    auto backend = make_backend(engine);
    RunOptions options;
    options.contact_mode = mode;
    backend->build(scene, options);
    return backend;
}

std::vector<Sample> sampled_run(const std::string& engine, const Scene& scene, const std::string& mode, double every) {
    auto backend = build_backend(engine, scene, mode);
    const double dt = backend->time_step();
    const long long steps = std::llround(scene.run.duration / dt);
    const long long stride = std::max(1LL, std::llround(every / dt));
    std::vector<Sample> out{backend->sample()};
    for (long long i = 1; i <= steps; ++i) {
        if (backend->step() != StepStatus::ok) throw Error(engine + " unstable: " + backend->failure());
        if (i % stride == 0 || i == steps) out.push_back(backend->sample());
    }
    return out;
}

double angle_about_y(const Quat& q) {
    Mat3 r = q.toRotationMatrix();
    return std::atan2(r(0, 2), r(2, 2));
}

const metrics::Metric& find_metric(const cases::CaseAnalysis& a, const std::string& name) {
    for (const auto& m : a.metrics)
        if (m.name == name) return m;
    FAIL("no metric " << name);
    return a.metrics.front();
}

int check_judged(const cases::CaseAnalysis& a) {
    int judged = 0;
    for (const auto& m : a.metrics) {
        if (!m.judged()) continue;
        ++judged;
        INFO(m.name << ": " << m.value << " against " << m.reference << " (" << m.tolerance_text() << "; " << m.basis << ")");
        CHECK(m.pass());
    }
    return judged;
}

}  // namespace cairn::test
