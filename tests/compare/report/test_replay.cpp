// the 3-D replay page: untrusted names cannot break out of its script, frames stay bounded
#include <catch2/catch.hpp>

#include "error.hpp"
#include "report/replay.hpp"
#include "scene/scene_builder.hpp"

using namespace cairn;

namespace {

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

Scene one_block(const std::string& name) {
    Scene scene;
    scene.materials.resize(1);
    add_box(scene, name, Vec3(1, 1, 1), Vec3(0, 0, 0.5), false);
    return scene;
}

}  // namespace

TEST_CASE("a block name cannot close the replay's script") {
    const std::string hostile = "</script><script>alert(1)</script>";
    ReplayRun run = replay_run("<b>dem</b>", one_block(hostile));
    Sample s;
    s.blocks.resize(1);
    add_frame(run, s);
    if (!replay_available()) {
        CHECK_THROWS_AS(replay_html("t", {run}), Error);
        return;
    }
    const std::string page = replay_html("<title>", {run});
    // the data script and the bundled script close once each; the names are in the data, escaped
    CHECK(count(page, "</script>") == 2);
    CHECK(count(page, "alert(1)") == 1);
    CHECK(count(page, "<title>&lt;title&gt;</title>") == 1);
}

TEST_CASE("a long run keeps a bounded number of evenly spaced frames") {
    ReplayRun run = replay_run("dem", one_block("A"));
    Sample s;
    s.blocks.resize(1);
    const int n = 10001;
    for (int k = 0; k < n; ++k) {
        s.t = 0.001 * k;
        add_frame(run, s);
    }
    REQUIRE(run.t.size() < kMaxReplayFrames);
    REQUIRE(run.t.size() == run.poses.size());
    // frame k holds sample k·stride: 10001 samples with stride 4 leave 2501 frames
    CHECK(run.stride == 4);
    CHECK(run.t.size() == 2501);
    for (size_t k = 0; k < run.t.size(); ++k) CHECK(run.t[k] == 0.001 * double(k * 4));
}

TEST_CASE("a scene of many blocks keeps fewer frames, within bounds") {
    CHECK(replay_frame_limit(1) == kMaxReplayFrames);
    CHECK(replay_frame_limit(300) == kMaxReplayNumbers / (7 * 300));   // 476 frames of a 300-brick wall
    CHECK(replay_frame_limit(1000000) == kMinReplayFrames);
}

TEST_CASE("the replay's view stands up against the scene's gravity") {
    Scene scene = one_block("A");
    CHECK(replay_run("dem", scene).up == Vec3::UnitZ());
    scene.gravity = Vec3(0, -9.81, 0);   // a Y-up scene
    const ReplayRun run = replay_run("dem", scene);
    CHECK(run.up == Vec3::UnitY());
    scene.gravity = Vec3::Zero();         // none: z
    CHECK(replay_run("dem", scene).up == Vec3::UnitZ());
    if (!replay_available()) return;
    CHECK(count(replay_html("t", {run}), "\"up\":[0.0,1.0,0.0]") == 1);
}
