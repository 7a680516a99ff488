// the blocks re-read in upright frames (compare/cases/upright_frames.cpp), the rotation angle the
// kinds measure from a run (case_util's angle_series), and a rise measured against gravity
#include <catch2/catch.hpp>

#include <cmath>

#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "cases/upright_frames.hpp"
#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

namespace {

BlockDef box(const Vec3& size, const Quat& q, const Vec3& at) {
    BlockDef b;
    b.name = "A";
    b.size = size;
    b.corners = box_corners(size);
    b.orientation = q;
    b.position = at;
    b.mesh.divisions = {2, 3, 5};
    return b;
}

}  // namespace

TEST_CASE("upright frames: a box standing along its frame y is re-read with its height along z, its geometry the same",
          "[cases]") {
    Scene s;
    s.gravity = Vec3(0, -9.81, 0);
    // turned a little about the vertical, so that no frame axis is a world axis
    s.blocks.push_back(box(Vec3(0.2, 1.0, 0.7), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitY())), Vec3(1, 0.5, 2)));
    LoadDef l;
    l.block = 0;
    l.point = Vec3(0.1, 0.5, -0.35);   // a top corner
    s.loads.push_back(l);
    const Scene u = cases::upright_frames(s);
    const BlockDef &a = s.blocks[0], &b = u.blocks[0];
    CHECK((b.orientation * Vec3::UnitZ()).dot(Vec3::UnitY()) == Approx(1.0).epsilon(1e-15));
    CHECK(b.size.z() == 1.0);
    // the frame axis along the height keeps its divisions (5 along the written y)
    CHECK(b.mesh.divisions[2] == 3);
    CHECK(b.mesh.divisions[0] * b.mesh.divisions[1] == 10);
    for (size_t i = 0; i < 8; ++i)   // 1e-15 m: the same corners in the world (a turn of the frame only)
        CHECK((a.position + a.orientation * a.corners[i] - (b.position + b.orientation * b.corners[i])).norm() < 1e-15);
    CHECK((a.orientation * s.loads[0].point - b.orientation * u.loads[0].point).norm() < 1e-15);
    // a block upside down is upright too; one already upright is copied to the bit
    s.blocks[0] = box(Vec3(0.2, 0.7, 1.0), Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX())), Vec3::Zero());
    CHECK((cases::upright_frames(s).blocks[0].orientation * Vec3::UnitZ()).y() == Approx(1.0));
    s.blocks[0] = box(Vec3(0.2, 0.7, 1.0), Quat(Eigen::AngleAxisd(-M_PI / 2, Vec3::UnitX())), Vec3::Zero());
    const BlockDef kept = cases::upright_frames(s).blocks[0];
    CHECK(kept.orientation.coeffs() == s.blocks[0].orientation.coeffs());
    CHECK(kept.corners == s.blocks[0].corners);
}

TEST_CASE("angle series: q and −q read the same angle, an unturned block 0", "[cases]") {
    std::vector<Sample> run(2);
    for (auto& x : run) x.blocks.resize(1);
    run[1].t = 1.0;
    run[0].blocks[0].orientation.coeffs() = -Quat::Identity().coeffs();
    run[1].blocks[0].orientation.coeffs() = -Quat(Eigen::AngleAxisd(0.3, Vec3::UnitY())).coeffs();
    const auto th = cases::angle_series(run, 0, Vec3::UnitY());
    CHECK(th.y[0] == 0.0);
    CHECK(th.y[1] == Approx(0.3).epsilon(1e-14));
}

TEST_CASE("upright frames: a fixed base is read by its side facing the reference block, at any slope", "[cases]") {
    // a 60° slope written Z-up, the block on its frame +z side: the base is kept as written (its
    // frame x is nearer up, but the block rests on the steep side)
    Scene s;
    const Quat tilt(Eigen::AngleAxisd(60.0 * M_PI / 180.0, Vec3::UnitY()));
    s.blocks.push_back(box(Vec3(6, 4, 0.5), tilt, Vec3::Zero()));
    s.blocks.back().fixed = true;
    s.blocks.push_back(box(Vec3(0.4, 0.4, 0.4), tilt, tilt * Vec3(0, 0, 0.45)));
    s.reference = ReferenceDef{"newmark", 1, {}};
    const Scene u = cases::upright_frames(s);
    CHECK(u.blocks[0].orientation.coeffs() == s.blocks[0].orientation.coeffs());
    CHECK(u.blocks[1].orientation.coeffs() == s.blocks[1].orientation.coeffs());
    // a 10° slope written Y-up, turned about x: the side towards the block becomes the base's +z
    s.gravity = Vec3(0, -9.81, 0);
    const Quat y_tilt(Eigen::AngleAxisd(10.0 * M_PI / 180.0, Vec3::UnitX()));
    s.blocks[0] = box(Vec3(6, 0.5, 4), y_tilt, Vec3::Zero());
    s.blocks[0].fixed = true;
    s.blocks[1] = box(Vec3(0.4, 0.4, 0.4), y_tilt, y_tilt * Vec3(0, 0.45, 0));
    const BlockDef base = cases::upright_frames(s).blocks[0];
    CHECK((base.orientation * Vec3::UnitZ()).isApprox(y_tilt * Vec3::UnitY(), 1e-15));
    CHECK(base.size.z() == 0.5);
}

TEST_CASE("rest kind: a Y-up scene's penetration is measured against gravity, as in its Z-up world", "[cases]") {
    // paper case (a) as a Y-up user writes it (x, y, z → x, z, −y; its cubes unturned), its run the
    // oracle's penetration along −y: the same metrics as the Z-up scene's run along −z
    const Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/stability.toml");
    const Mat3 m = (Mat3() << 1, 0, 0, 0, 0, 1, 0, -1, 0).finished();
    Scene y = s;
    y.gravity = m * s.gravity;
    for (auto& b : y.blocks) b.position = m * b.position;
    for (auto& p : y.probes) p.point = m * p.point;
    const auto& kind = cases::case_kind("rest", s.source);
    std::vector<double> t;
    for (int i = 0; i <= 500; ++i) t.push_back(1e-3 * i);
    const auto pen = kind.curve(s, {}, t);
    auto run = [&](const Scene& w, const Vec3& down) {
        std::vector<Sample> out;
        for (size_t i = 0; i < t.size(); ++i) {
            Sample x;
            x.t = t[i];
            x.blocks.resize(1);
            x.blocks[0].position = w.blocks.at(size_t(w.reference->block)).position + pen[i] * down;
            x.probes.push_back(w.probes[0].point + pen[i] * down);   // where the block is; only its motion is read
            out.push_back(x);
        }
        return out;
    };
    const auto z = kind.analyse(s, run(s, -Vec3::UnitZ()), {});
    const auto w = kind.analyse(y, run(y, -Vec3::UnitY()), {});
    REQUIRE(z.metrics.size() == 3);
    REQUIRE(w.metrics.size() == z.metrics.size());
    for (size_t k = 0; k < z.metrics.size(); ++k) {
        INFO(z.metrics[k].name);
        CHECK(z.metrics[k].pass());
        CHECK(w.metrics[k].value == Approx(z.metrics[k].value).epsilon(1e-12));
        CHECK(w.metrics[k].pass());
    }
}

TEST_CASE("upright frames: a base under a block it carries off its centre is read by its top, not its nearer side",
          "[cases]") {
    // a lintel 3 m long over a 0.5 m pillar's edge (its centre 1.5 m aside, 0.1 m above the top),
    // written Z-up and Y-up: the pillar's top faces it in both (the side lies nearer its centre)
    for (bool y_up : {false, true}) {
        INFO((y_up ? "Y-up" : "Z-up"));
        Scene s;
        s.gravity = y_up ? Vec3(0, -9.81, 0) : Vec3(0, 0, -9.81);
        const Vec3 pillar = y_up ? Vec3(0.5, 2.0, 0.5) : Vec3(0.5, 0.5, 2.0);
        s.blocks.push_back(box(pillar, Quat::Identity(), Vec3::Zero()));
        s.blocks.back().fixed = true;
        const Vec3 lintel = y_up ? Vec3(3.0, 0.2, 0.5) : Vec3(3.0, 0.5, 0.2);
        s.blocks.push_back(box(lintel, Quat::Identity(), y_up ? Vec3(1.5, 1.1, 0) : Vec3(1.5, 0, 1.1)));
        s.reference = ReferenceDef{"pushover", 1, {}};
        const Scene u = cases::upright_frames(s);
        CHECK((u.blocks[0].orientation * Vec3::UnitZ()).isApprox(-s.gravity.normalized(), 1e-15));
        CHECK((u.blocks[1].orientation * Vec3::UnitZ()).isApprox(-s.gravity.normalized(), 1e-15));
        CHECK(u.blocks[0].size.z() == 2.0);
        if (!y_up) CHECK(u.blocks[0].orientation.coeffs() == s.blocks[0].orientation.coeffs());
    }
}

TEST_CASE("kinds' refusals name a block's height and the side it rests on, not a frame axis", "[cases]") {
    // the kinds read boxes in re-read frames, so a refusal naming "frame z" would name an axis the
    // user of a Y-up scene did not write: housner leaning other than theta0, a tilted block under
    // slide
    auto refusal = [](const std::string& kind, const Scene& scene) {
        try {
            cases::case_kind(kind, scene.source).check(scene);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    auto names_frame = [](const std::string& m) {
        return m.find("frame z") != std::string::npos || m.find("block-frame") != std::string::npos;
    };
    Scene h = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/rocking_housner.toml");
    h.reference->values["theta0"] += 0.01;   // rad, past the 1e-3 rad the check allows
    const std::string lean = refusal("housner", h);
    INFO(lean);
    CHECK(lean.find("height") != std::string::npos);
    CHECK_FALSE(names_frame(lean));

    Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/friction_slide.toml");
    s.blocks.at(size_t(s.reference->block)).orientation = Quat(Eigen::AngleAxisd(0.3, Vec3::UnitX()));   // tilted 0.3 rad
    const std::string tilted = refusal("slide", s);
    INFO(tilted);
    CHECK(tilted.find("tilted") != std::string::npos);
    CHECK_FALSE(names_frame(tilted));
}
