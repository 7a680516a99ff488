// the VTK writer: file names from scene names, posed rigid blocks and their fields, file layout
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "output/vtk_series.hpp"
#include "scene/scene_builder.hpp"

using namespace cairn;

namespace {

/// a backend that only answers what blocks_grid asks (no deformable meshes)
class NoMeshBackend : public Backend {
public:
    std::string name() const override { return "none"; }
    std::string engine_version() const override { return "none"; }
    void build(const Scene&, const RunOptions&) override {}
    double time_step() const override { return 1.0; }
    double critical_step() const override { return 0.0; }
    StepStatus step() override { return StepStatus::ok; }
    Sample sample() const override { return {}; }
};

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("scene names become safe file names") {
    CHECK(safe_file_stem("wall-2_b") == "wall-2_b");
    CHECK(safe_file_stem("../../etc/passwd") == "______etc_passwd");
    CHECK(safe_file_stem("a b\nc") == "a_b_c");
    CHECK(safe_file_stem("") == "scene");
    CHECK(safe_file_stem(std::string(100, 'x')).size() == 64);
}

TEST_CASE("a rigid block is one hexahedron posed by its sampled centre and orientation") {
    Scene scene;
    scene.materials.resize(1);
    add_box(scene, "base", Vec3(2, 2, 1), Vec3(0, 0, -0.5), true);
    add_box(scene, "A", Vec3(0.4, 0.2, 1.0), Vec3(0, 0, 0.5), false);
    // turned a quarter turn about z, moving along x and spinning about z
    Sample s;
    BlockState st;
    st.position = Vec3(1.0, 2.0, 3.0);
    st.orientation = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
    st.velocity = Vec3(0.5, 0, 0);
    st.angular_velocity = Vec3(0, 0, 2.0);
    s.blocks.push_back(st);
    const VtkGrid g = blocks_grid(scene, s, NoMeshBackend());
    REQUIRE(g.points.size() == 16);
    REQUIRE(g.cells() == 2);
    // corner 6 of A is (+0.2, +0.1, +0.5) in its frame: turned about z it is (-0.1, +0.2, +0.5)
    const Vec3 c6 = g.points[8 + 6];
    CHECK((c6 - Vec3(0.9, 2.2, 3.5)).norm() < 1e-15);
    // its velocity v + ω × r = (0.5, 0, 0) + (0, 0, 2) × (-0.1, 0.2, 0.5) = (0.1, -0.2, 0)
    const auto& pv = g.point_fields[1];
    REQUIRE(pv.name == "velocity");
    CHECK(std::abs(pv.values[3 * 14 + 0] - 0.1) < 1e-15);
    CHECK(std::abs(pv.values[3 * 14 + 1] + 0.2) < 1e-15);
    // cell fields: the block's index, velocity, angular velocity and a quarter turn
    CHECK(g.cell_fields[0].values == std::vector<double>{0, 1});
    CHECK(g.cell_fields[1].values[3] == 0.5);
    CHECK(g.cell_fields[2].values[5] == 2.0);
    CHECK(g.cell_fields[3].values[0] == 0.0);
    CHECK(std::abs(g.cell_fields[3].values[1] - M_PI / 2) < 1e-15);
    // the fixed base keeps its scene pose: its top at z = 0
    for (int k = 4; k < 8; ++k) CHECK(g.points[k].z() == 0.0);
}

TEST_CASE("vtu and pvd files say what they hold") {
    VtkGrid g = contacts_grid({ContactPoint{Vec3(1, 2, 3), Vec3::UnitZ(), Vec3(0, 0, 5), Vec3(1, 0, 0), 1, 0}});
    std::ostringstream vtu;
    write_vtu(vtu, g);
    const std::string v = vtu.str();
    CHECK(count(v, "NumberOfPoints=\"1\" NumberOfCells=\"1\"") == 1);
    CHECK(count(v, "Name=\"normal_force\" NumberOfComponents=\"3\"") == 1);
    CHECK(count(v, "Name=\"types\" format=\"ascii\">\n1\n") == 1);   // VTK_VERTEX
    std::ostringstream pvd;
    write_pvd(pvd, {{0.0, "a_000000.vtu"}, {0.25, "a_000001.vtu"}});
    CHECK(count(pvd.str(), "<DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"a_000001.vtu\"/>") == 1);
}
