// trajectory CSV: the column layout, and numbers that read back bit for bit
#include <catch2/catch.hpp>

#include <cstdlib>
#include <sstream>

#include "../run/fake_backend.hpp"
#include "output/trajectory_csv.hpp"

using namespace cairn;

namespace {

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) out.push_back(cell);
    return out;
}

}  // namespace

TEST_CASE("trajectory columns: t, probes, free blocks, energies, contacts, each with its unit", "[output]") {
    Scene scene = testing::ballistic_scene();
    scene.probes.push_back({"Q", 1, Vec3::Zero()});   // a probe on the fixed block is recorded too
    const std::vector<std::string> expected{
        "t [s]",     "P.x [m]",     "P.y [m]",      "P.z [m]",  "Q.x [m]",      "Q.y [m]",
        "Q.z [m]",   "A.x [m]",     "A.y [m]",      "A.z [m]",  "A.qw [-]",     "A.qx [-]",
        "A.qy [-]",  "A.qz [-]",    "E_kinetic [J]", "E_potential [J]", "E_contact [J]", "E_strain [J]",
        "E_dissipated [J]", "W_external [J]", "E_balance_error [J]", "contacts [-]"};
    CHECK(trajectory_columns(scene) == expected);
}

TEST_CASE("trajectory rows round-trip exactly with 17 significant digits", "[output]") {
    const Scene scene = testing::ballistic_scene();
    Sample s0;
    s0.t = 0.0;
    s0.probes = {Vec3(0.1, 1.0 / 3.0, -2.5e17)};
    BlockState b;
    b.position = Vec3(1e-300, -0.7, 2.0 / 3.0);
    b.orientation = Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
    s0.blocks = {b};
    s0.energy.kinetic = 1.0 / 7.0;
    s0.energy.potential = 19.62;
    Sample s1 = s0;
    s1.t = 0.1;
    s1.energy.kinetic = 0.1;
    s1.energy.contact = 3e-9;
    s1.energy.strain = 0.0;
    s1.energy.dissipated = 4.0 / 3.0;
    s1.energy.external = 0.25;
    s1.contacts = 12;

    std::ostringstream out;
    write_trajectory_csv(out, scene, {s0, s1});
    std::istringstream in(out.str());
    std::string line;
    REQUIRE(std::getline(in, line));
    CHECK(split(line) == trajectory_columns(scene));

    std::vector<std::vector<std::string>> rows;
    while (std::getline(in, line)) rows.push_back(split(line));
    REQUIRE(rows.size() == 2);
    const auto& r = rows[1];
    REQUIRE(r.size() == 19);
    auto num = [&](int i) { return std::strtod(r[size_t(i)].c_str(), nullptr); };
    CHECK(num(0) == 0.1);
    CHECK(num(1) == 0.1);
    CHECK(num(2) == 1.0 / 3.0);
    CHECK(num(3) == -2.5e17);
    CHECK(num(4) == 1e-300);
    CHECK(num(5) == -0.7);
    CHECK(num(6) == 2.0 / 3.0);
    CHECK(num(7) == b.orientation.w());
    CHECK(num(8) == b.orientation.x());
    CHECK(num(9) == b.orientation.y());
    CHECK(num(10) == b.orientation.z());
    CHECK(num(11) == 0.1);
    CHECK(num(12) == 19.62);
    CHECK(num(13) == 3e-9);
    CHECK(num(14) == 0.0);
    CHECK(num(15) == 4.0 / 3.0);
    CHECK(num(16) == 0.25);
    // the balance error is total() minus the first sample's total()
    CHECK(num(17) == s1.energy.total() - s0.energy.total());
    CHECK(r[18] == "12");
    // the first row's balance error is exactly zero
    CHECK(rows[0][17] == "0");
}

TEST_CASE("a sample that does not match the scene is refused", "[output]") {
    const Scene scene = testing::ballistic_scene();
    Sample s;   // no probe, no block
    std::ostringstream out;
    CHECK_THROWS(write_trajectory_csv(out, scene, {s}));
}
