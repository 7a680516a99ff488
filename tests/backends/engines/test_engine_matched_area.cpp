// the matched penalty spring on the face that actually bears the contact (a brick on its side and
// on its end, a frustum, a head joint) and a drum column rocking under a pulse in matched mode:
// every backend with a matched mode through the same test body
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "engine_scenes.hpp"
#include "geometry/hexahedron.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;
using namespace cairn::test;

namespace {

constexpr double g = 9.81;
constexpr double kPi = 3.14159265358979323846;
constexpr double kn = 3e7;   // N/m³, base_scene's

// step `backend` for `duration` s, failing on an unstable step; returns the last sample
Sample settle(Backend& backend, const std::string& engine, double duration) {
    const long long steps = std::llround(duration / backend.time_step());
    for (long long i = 0; i < steps; ++i)
        if (backend.step() != StepStatus::ok) FAIL(engine << " unstable: " << backend.failure());
    return backend.sample();
}

}  // namespace

namespace {

// the sink (m) of block 0 of `s` after 0.5 s on `engine`, matched contact, and its closed form
// W/(kn A) for bearing area `area` (m²); the block starts just touching the base's top z = 0
void check_sink(const std::string& engine, const std::string& label, Scene& s, double mass, double area) {
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.5;   // settles within 0.1 s (slowest period 13 ms)
    add_box(s, "base", Vec3(1.0, 1.0, 0.5), Vec3(0, 0, -0.25), true);
    const BlockDef& d = s.blocks[0];
    REQUIRE(mass_properties(d.corners, 2600.0).mass == Approx(mass).epsilon(1e-12));
    // centre of mass at t = 0, world
    const double z0 = (d.position + d.orientation * mass_properties(d.corners, 2600.0).centre).z();
    auto b = build_backend(engine, s, "matched");
    Sample x = settle(*b, engine, 0.5);
    const double sink = z0 - x.blocks[0].position.z();
    const double expected = mass * g / (kn * area);
    CAPTURE(sink, expected, (sink - expected) / expected);
    WARN(engine << " " << label << ": sinks " << sink << " m against W/(kn A) " << expected << " m ("
                << (sink - expected) / expected * 100 << " %)");
    // the static spring is exact on every engine (the stack test: 0.00 %); 1 % leaves room for what
    // is left of the damped oscillation after 0.5 s (e^-60 of it) and for MuJoCo's creeping friction;
    // a wrong face is off by 2x
    CHECK(sink == Approx(expected).epsilon(0.01));
}

}  // namespace

TEST_CASE("every backend: a matched brick settles by W/(kn A) of the face it stands on", "[engines][matched]") {
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    // flat: a brick 0.4 x 0.2 x 0.2 m on its 0.4 x 0.2 face (face 0); end: the same brick turned 90
    // degrees about y, on its 0.2 x 0.2 end (face 0 is then vertical): 1.70e-4 m and 3.40e-4 m
    const std::string pose = GENERATE(as<std::string>{}, "flat", "end");
    CAPTURE(engine, pose);
    Scene s = base_scene("brick_" + pose);
    if (pose == "end")
        add_box(s, "A", Vec3(0.4, 0.2, 0.2), Vec3(0, 0, 0.2), false, Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitY())));
    else
        add_box(s, "A", Vec3(0.4, 0.2, 0.2), Vec3(0, 0, 0.1), false);
    check_sink(engine, pose, s, 2600.0 * 0.016, pose == "end" ? 0.2 * 0.2 : 0.4 * 0.2);
}

// Bullet misses: a convex hull on a box collides through GJK with the hull's margin outside its
// corners and keeps one manifold point, so the frustum floats 0.49 mm above the base (on a hull
// base it sinks +82 %; docs/backends.md); the face rule's side is pinned in test_engine_bearing_area
TEST_CASE("every backend: a matched frustum settles by W/(kn A) of its wide face", "[engines][matched][!mayfail]") {
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    CAPTURE(engine);
    // 0.4 x 0.2 below, 0.2 x 0.2 above, 0.2 m high, on its wide face: its opposite face differs, so a
    // normal taken on the wrong side of the pair would take the narrow top face (2x the sink)
    Scene s = base_scene("frustum");
    int i = add_box(s, "A", Vec3(0.4, 0.2, 0.2), Vec3(0, 0, 0.1), false);
    BlockDef& d = s.blocks[i];
    d.shape = Shape::hexahedron;
    for (Vec3& c : d.corners)
        if (c.z() > 0) c.x() *= 0.5;
    // the section shrinks linearly with height: the volume is the height times the mean of the faces
    check_sink(engine, "frustum", s, 2600.0 * 0.2 * (0.4 * 0.2 + 0.2 * 0.2) / 2.0, 0.4 * 0.2);
}

TEST_CASE("every backend: a matched head joint springs over the brick's end and not its bed face", "[engines][matched]") {
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    CAPTURE(engine);
    // no gravity: a brick 0.4 x 0.2 x 0.2 pushed along -x by 400 N against a fixed abutment whose
    // face towards it (0.6 x 0.6) and whose face 0 (0.3 x 0.6) both differ from the brick's end
    Scene s = base_scene("head_joint");
    s.gravity = Vec3::Zero();
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.5;
    add_box(s, "A", Vec3(0.4, 0.2, 0.2), Vec3(0.2, 0, 0), false);
    add_box(s, "wall", Vec3(0.3, 0.6, 0.6), Vec3(-0.15, 0, 0), true);
    LoadDef push;
    push.block = 0;
    push.force = Vec3(-400.0, 0, 0);
    push.point = Vec3::Zero();   // the brick's centre: no moment
    s.loads.push_back(push);
    auto b = build_backend(engine, s, "matched");
    Sample x = settle(*b, engine, 0.5);
    const double overlap = -(x.blocks[0].position.x() - 0.2);
    const double expected = 400.0 / (kn * 0.2 * 0.2);   // 3.33e-4 m
    CAPTURE(overlap, expected, (overlap - expected) / expected);
    WARN(engine << " head joint: " << overlap << " m against P/(kn A_end) " << expected << " m ("
                << (overlap - expected) / expected * 100 << " %)");
    // as above: the static spring is exact, 1 % for the residual oscillation; face 0 would give half
    CHECK(overlap == Approx(expected).epsilon(0.01));
}

TEST_CASE("reference engines: a matched drum column rocks alike under a one-sine pulse", "[engines][matched]") {
    // the three drums of scenarios/structures/column_pushover (0.4 x 0.4 x 0.5 m, kn 1e9 N/m³)
    // under a 0.35 g, 1.5 Hz one-sine pulse along x: the column uplifts (B/H = 0.267) and rocks
    std::string toml = shipped_scene_text("structures/column_pushover.toml");
    std::ostringstream t, a;
    const double hz = 1.5;
    for (int i = 0; i <= 100; ++i) {
        const double ti = i / (100 * hz);
        t << (i ? ", " : "") << ti;
        a << (i ? ", " : "") << 0.35 * std::sin(2 * kPi * hz * ti);
    }
    const size_t from = toml.find("[ground_motion]"), to = toml.find("[probes.top]");
    REQUIRE(from != std::string::npos);
    REQUIRE(to != std::string::npos);
    toml.replace(from, to - from,
                 "[ground_motion]\ntime = [" + t.str() + "]\nacceleration = [" + a.str() + "]\nunits = \"g\"\n\n");
    const Scene s = parse_scene(toml, "<column pulse>", {parse_override("run.duration=1.5")});
    std::vector<std::string> engines;
    std::vector<double> peaks;
    for (const std::string& engine : engine_names()) {
        if (!has_matched_mode(engine)) continue;
        auto b = build_backend(engine, s, "matched");
        double peak = 0.0;
        const long long steps = std::llround(s.run.duration / b->time_step());
        for (long long i = 0; i < steps; ++i) {
            if (b->step() != StepStatus::ok) FAIL(engine << " unstable: " << b->failure());
            peak = std::max(peak, std::abs(angle_about_y(b->sample().blocks[2].orientation)));
        }
        WARN(engine << " matched: top drum's peak rotation " << peak << " rad");
        engines.push_back(engine);
        peaks.push_back(peak);
    }
    REQUIRE(peaks.size() >= 2);
    std::vector<double> sorted = peaks;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[sorted.size() / 2];
    for (size_t i = 0; i < peaks.size(); ++i) {
        CAPTURE(engines[i], peaks[i], median);
        // the column really rocked (elastic sway alone stays below 1e-3 rad)
        CHECK(peaks[i] > 0.05);
        // measured 0.1295 (Bullet), 0.1295 (ODE), 0.1281 (MuJoCo): the engines resolve the rocking
        // impacts differently (sequential impulses, an LCP, soft constraints with creeping
        // friction), so 5 % of the median; MuJoCo's own box-box collider gave 3.14 rad (overturned)
        CHECK(peaks[i] == Approx(median).epsilon(0.05));
    }
}

TEST_CASE("every backend: a 2 cm cube on matched springs of 1e12 N/m³ rests with dt = auto", "[engines][matched]") {
    // kn·A = 4e8 N/m on 20.8 g: ω = 1.4e5 rad/s, so the reference engines' default step of 1e-4 s
    // is 14 of 1/ω; MuJoCo's matched contact blew up there ("energy growing without a source" at
    // 0.09 s) and now takes dt = 1/ω of its stiffest spring bed (3.7e-6 s)
    const std::string engine = GENERATE(from_range(matched_backend_names()));
    CAPTURE(engine);
    Scene s = base_scene("tiny_cube");
    s.run.dt.reset();   // dt = auto
    s.contact.kn = s.contact.ks = 1e12;
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.5;   // settles within a few of its 45 µs periods
    add_box(s, "A", Vec3(0.02, 0.02, 0.02), Vec3(0, 0, 0.01), false);
    add_box(s, "base", Vec3(1.0, 1.0, 0.5), Vec3(0, 0, -0.25), true);
    auto b = build_backend(engine, s, "matched");
    const Sample x = settle(*b, engine, 0.05);
    // the static sink W/(kn·A) = 5.1e-10 m; the engines rest within 1e-7 m of the placed height (a
    // blow-up leaves at once), and no faster than the gravity's 1e-5 m/s over one step
    CHECK(std::abs(x.blocks[0].position.z() - 0.01) < 1e-7);
    CHECK(x.blocks[0].velocity.norm() < 1e-5);
}
