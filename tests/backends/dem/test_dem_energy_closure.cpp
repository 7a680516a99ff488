// Every shipped scene closes its energy balance within 0.1 % of the energy of its motion (the
// runner's max_balance_error, written in run.json: docs/dem.md, Energy) on dem, rigid and
// deformable, paper and overlap schemes, at the default time step (docs/dem.md, Energy, lists the
// cases that still miss with their numbers).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "dem/dem_backend.hpp"
#include "run/runner.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

namespace {

// the bound of the issue: 0.1 % of the motion energy
constexpr double kClosure = 1e-3;

// largest |balance error| / motion energy of a shipped scene run to its end on dem
double max_balance_error(const std::string& scene, const std::string& scheme, const std::string& model,
                         const std::string& dt_safety = "") {
    std::vector<Override> set{{"contact.scheme", "\"" + scheme + "\""}};
    if (!dt_safety.empty()) set.push_back({"run.dt_safety", dt_safety});
    Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/" + scene + ".toml", set);
    apply_model(s, model);
    auto backend = dem_backend_info().make();
    const RunResult r = run_scene(*backend, s, RunOptions{});
    INFO(scene << " " << scheme << " " << model << ": " << r.message);
    REQUIRE(r.status == RunStatus::completed);
    return r.max_balance_error;
}

void check_closes(const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                  const std::string& model, const std::string& dt_safety = "") {
    for (const auto& scene : scenes)
        for (const auto& scheme : schemes) {
            const double e = max_balance_error(scene, scheme, model, dt_safety);
            INFO(scene << ", " << scheme << " scheme, " << model << (dt_safety.empty() ? "" : ", dt_safety ")
                       << dt_safety << ": max balance error " << e << " of the motion energy");
            CHECK(e < kClosure);
        }
}

// a scene of tests/backends/dem/ (with overrides), rigid and deformable: its largest balance error
// within the bound
void check_test_scene_closes(const std::string& file, const std::vector<Override>& set) {
    for (const std::string model : {"rigid", "deformable"}) {
        Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/tests/backends/dem/" + file, set);
        apply_model(s, model);
        auto backend = dem_backend_info().make();
        const RunResult r = run_scene(*backend, s, RunOptions{});
        REQUIRE(r.status == RunStatus::completed);
        INFO(file << ", " << model << ": max balance error " << r.max_balance_error << " of the motion energy");
        CHECK(r.max_balance_error < kClosure);
    }
}

// a 0.4 x 0.2 x 0.2 m brick tilted 0.3 rad about (1, 1, 0), thrown down at 7 m/s (and 1 m/s along
// x) onto a fixed brick of its own size: its corner and edges land across the fixed brick's edges
Scene brick_on_edge(const std::string& model) {
    Scene s = parse_scene(
        "[run]\nduration = 0.03\noutput_interval = 0.0001\n"
        "[materials.stone]\ndensity = 2600\nyoung = 30e9\npoisson = 0.2\n"
        "[contact]\nkn = 1e9\nfriction = 0.7\ndamping_ratio = 0.1\n"
        "[blocks.A]\nsize = [0.4, 0.2, 0.2]\nposition = [0, 0, 0.4]\n"
        "orientation = {axis = [1, 1, 0], angle = 0.3}\nvelocity = [1, 0, -7]\nmaterial = \"stone\"\n"
        "[blocks.A.mesh]\ndivisions = [2, 1, 1]\n"
        "[blocks.C]\nsize = [0.4, 0.2, 0.2]\nposition = [0, 0, 0.1]\nmaterial = \"stone\"\nfixed = true\n",
        "<brick on an edge>");
    apply_model(s, model);
    return s;
}

// the kinetic energy of the last sample at or before t_max, J
struct KineticAt : SampleSink {
    double t_max, kinetic = 0.0;
    explicit KineticAt(double t) : t_max(t) {}
    void sample(const Sample& x) override {
        if (x.t <= t_max) kinetic = x.energy.kinetic;
    }
};

}  // namespace

TEST_CASE("rigid blocks close the energy balance of the paper's scenes at the default step", "[dem][energy]") {
    check_closes({"paper/friction_slide", "paper/friction_stick", "paper/friction_stick_base", "paper/rocking_damped_02",
                  "paper/rocking_damped_04", "paper/rocking_housner", "paper/rocking_slender"},
                 {"paper", "overlap"}, "rigid");
}

TEST_CASE("rigid blocks close the energy balance of rocking that overturns and of rolling", "[dem][energy]") {
    // overlap scheme: the rocking block overturns and lands across the base's edge, the rolling
    // cube's edge impact sweeps its contact areas fast (1.43 % and 0.110 % before the edge forces
    // and the shear offset's mean √A; docs/dem.md, Energy)
    check_closes({"paper/rocking", "paper/rolling"}, {"paper", "overlap"}, "rigid");
    check_closes({"paper/rocking_winkler"}, {"overlap"}, "rigid");   // ships on the overlap scheme
}

TEST_CASE("rigid blocks close the energy balance of the hard impacts at the default step", "[dem][energy]") {
    // the step's kinetic energy leaves out the half kick's (dt²/8)·F²/m, which ½mv² carried at the
    // impact's peak: 0.10-0.24 % of the motion energy at the default dt_safety 0.1 before
    check_closes({"paper/impact", "paper/impact_damped", "paper/stability"}, {"paper", "overlap"}, "rigid");
}

TEST_CASE("deformable blocks close the energy balance of impacts, sliding and rolling, paper scheme", "[dem][energy]") {
    check_closes({"paper/friction_slide", "paper/impact", "paper/impact_damped", "paper/rolling", "paper/stability"},
                 {"paper"}, "deformable");
}

TEST_CASE("deformable blocks close the energy balance of rocking, paper scheme", "[dem][energy]") {
    check_closes({"paper/rocking", "paper/rocking_damped_02", "paper/rocking_damped_04", "paper/rocking_housner",
                  "paper/rocking_slender"},
                 {"paper"}, "deformable");
}

TEST_CASE("a deformable block sticking under a lifting load closes its energy balance, paper scheme", "[dem][energy]") {
    check_closes({"paper/friction_stick"}, {"paper"}, "deformable");
}

TEST_CASE("a deformable block sticking on a long base closes its energy balance, paper scheme", "[dem][energy]") {
    check_closes({"paper/friction_stick_base"}, {"paper"}, "deformable");
}

TEST_CASE("deformable blocks close the energy balance of the impacts and rolling, overlap scheme", "[dem][energy]") {
    check_closes({"paper/friction_slide", "paper/impact", "paper/impact_damped", "paper/rolling", "paper/stability"},
                 {"overlap"}, "deformable");
}

TEST_CASE("deformable blocks close the energy balance of rocking, overlap scheme", "[dem][energy]") {
    check_closes({"paper/rocking", "paper/rocking_slender"}, {"overlap"}, "deformable");
}

TEST_CASE("deformable blocks close the energy balance of damped rocking, overlap scheme", "[dem][energy]") {
    check_closes({"paper/rocking_damped_02", "paper/rocking_damped_04"}, {"overlap"}, "deformable");
}

TEST_CASE("a deformable block rocking on a rigid base closes its energy balance, overlap scheme", "[dem][energy]") {
    check_closes({"paper/rocking_housner"}, {"overlap"}, "deformable");
}

TEST_CASE("rigid arches close the energy balance, overlap scheme", "[dem][energy]") {
    // the arch on the paper scheme misses it (docs/dem.md, Energy); arch_thick and arch_thin state
    // the overlap scheme
    check_closes({"structures/arch", "structures/arch_thick", "structures/arch_thin"}, {"overlap"}, "rigid");
}

TEST_CASE("a rigid column closes the energy balance under El Centro", "[dem][energy]") {
    check_closes({"earthquake/column_elcentro"}, {"paper", "overlap"}, "rigid");
}

TEST_CASE("a block under ground pulses closes the energy balance, rigid and deformable", "[dem][energy]") {
    // a pulse beyond friction (the slide's friction work) and one below it (the onset's slip)
    for (const char* model : {"rigid", "deformable"})
        check_closes({"earthquake/block_pulse_slide", "earthquake/block_pulse_hold"}, {"paper", "overlap"}, model);
}

TEST_CASE("a block sliding down a slope under a ground pulse closes the energy balance, rigid and deformable",
          "[dem][energy]") {
    // gravity's work along the plane and the slide's friction work (the block's frame tilted with it)
    for (const char* model : {"rigid", "deformable"})
        check_closes({"earthquake/slope_pulse_slide"}, {"paper", "overlap"}, model);
}

TEST_CASE("a block rocking or overturning under a ground pulse closes the energy balance", "[dem][energy]") {
    // the one-sine pulses of the ground_rocking scenes: the drive's work in, rocking impacts out.
    // The overturning block lands on its side: on its own (overlap) scheme it closes (measured
    // 0.072 / 0.081 %), on the paper's grid it misses (0.19 / 0.14 %; docs/dem.md, Energy)
    for (const char* model : {"rigid", "deformable"}) {
        check_closes({"earthquake/block_pulse_rock"}, {"paper", "overlap"}, model);
        check_closes({"earthquake/block_pulse_overturn"}, {"overlap"}, model);
    }
}

TEST_CASE("a trilithon rocking under a ground pulse closes the energy balance", "[dem][energy]") {
    // two posts and a lintel, every joint opening and landing (measured 3.2e-6 of the energy scale
    // rigid, 1.1e-5 deformable, overlap scheme; paper scheme 8.9e-6 and 3.3e-4)
    for (const char* model : {"rigid", "deformable"})
        check_closes({"earthquake/frame_pulse_rock"}, {"paper", "overlap"}, model);
}

TEST_CASE("a stack of drums rocking on one another under a ground pulse closes the energy balance", "[dem][energy]") {
    // three drums, the base and two bed joints opening and landing
    for (const char* model : {"rigid", "deformable"}) check_closes({"earthquake/stack_pulse_rock"}, {"overlap"}, model);
}

TEST_CASE("a rigid column closes the energy balance under a pushover", "[dem][energy]") {
    check_closes({"structures/column_pushover"}, {"paper", "overlap"}, "rigid");
}

TEST_CASE("a deformable arch closes the energy balance, overlap scheme", "[dem][energy]") {
    check_closes({"structures/arch"}, {"overlap"}, "deformable");
}

TEST_CASE("a deformable arch near its thinnest closes the energy balance, overlap scheme", "[dem][energy]") {
    check_closes({"structures/arch_thin"}, {"overlap"}, "deformable");
}

TEST_CASE("a deformable arch just above its thinnest closes the energy balance, overlap scheme", "[dem][energy]") {
    // one sub-contact per joint face on hex8 blocks: it gained 48 % of its motion energy while
    // the normal force of a warped element face, applied at the pressure centre by the shape
    // functions, was not the gradient of the energy booked for it, and 0.96 % (first order in
    // dt) while the shear spring acted at the pressure centre (docs/dem.md, "scheme = overlap");
    // measured 0.021 %
    check_closes({"structures/arch_thick"}, {"overlap"}, "deformable");
}

TEST_CASE("a deformable column closes the energy balance under El Centro", "[dem][energy]") {
    check_closes({"earthquake/column_elcentro"}, {"paper", "overlap"}, "deformable");
}

TEST_CASE("the step's kinetic energy closes the balance of a block settling on linear springs to round-off", "[dem][energy]") {
    // paper case (a): the cube settles on its base's springs with no slip, no damping and no point
    // entering or leaving, so every force is linear in the positions and the central-difference
    // step keeps ½v⁻ᵀM(2v − v⁻) + U exactly; ½mv² + U carried (dt²/8)·F²/m, 0.24 % of the motion.
    // 1e-9: round-off of the ~10⁴ steps' sums, far below that
    for (const std::string scheme : {"paper", "overlap"}) {
        const double e = max_balance_error("paper/stability", scheme, "rigid");
        INFO(scheme << " scheme: max balance error " << e << " of the motion energy");
        CHECK(e < 1e-9);
    }
}

TEST_CASE("a brick landing across the edges of another closes its energy balance, rigid and deformable", "[dem][energy]") {
    // the overlap of its faces ends on the fixed brick's edges with depth: the boundary term of
    // the energy's gradient. Left out on deformable faces, 7.4 % of the motion energy vanished
    // unbooked (measured max 7.9 %, and the brick bounced off with 4 % more kinetic energy);
    // with it 0.096 % (rigid 0.082 %), against the 0.1 %
    double kinetic[2] = {0.0, 0.0};
    int i = 0;
    for (const std::string model : {"rigid", "deformable"}) {
        const Scene s = brick_on_edge(model);
        auto backend = dem_backend_info().make();
        KineticAt sink(0.0175);   // s: between the first impact (0.007-0.016 s) and the second (from 0.019 s)
        const RunResult r = run_scene(*backend, s, RunOptions{}, sink);
        REQUIRE(r.status == RunStatus::completed);
        INFO(model << ": max balance error " << r.max_balance_error << " of the motion energy");
        CHECK(r.max_balance_error < kClosure);
        kinetic[i++] = sink.kinetic;
    }
    // the stone's compliance (E = 30 GPa against kn = 1e9 N/m³ over 0.2 m) keeps the strain
    // energy below 1 J of the 1058 J: the bounce is the rigid brick's within 1 % (measured 0.2 %)
    CHECK(kinetic[1] == Approx(kinetic[0]).epsilon(0.01));
}

TEST_CASE("a wall shaken off its base closes its energy balance while its bricks tumble on each other's edges", "[dem][energy]") {
    // overlap scheme, at half the default step, to 2.2 s. Rigid: at 1.8379 s a brick turns through
    // 45° with its edge 3 mm in the corner of the brick below; its side on the bisector of that
    // brick's top and side had the cut between them parallel to it, and the cut's edge force
    // (0.32 MN in one step) made 51.7 J, 3.3 % of the motion energy. Deformable: the same made 16 J
    // at 2.149 s, 1.0 %. With the region beyond the cut: 0.0092 % rigid and 0.014 % deformable over
    // the whole 3 s, against the 0.1 %
    check_test_scene_closes("wall_shaken.toml", {{"run.dt_safety", "0.05"}, {"run.duration", "2.2"}});
}

TEST_CASE("a block overturning under a record closes its energy balance as it lands on its side, undamped", "[dem][energy]") {
    // the landing's shear springs stick, then slip as the face lifts off again, while the pressed
    // cells' area centroids run across the face. Their offsets grew with the relative motion at the
    // new centroid only, and slip was booked from the offsets rescaled to the new area instead of
    // the forces that acted: 0.152 % of the motion energy rigid, 0.114 % deformable (+2.3 J in the
    // two steps as the first landing let go). Growing with the mean motion at the last and the new
    // centroid, and booking slip as the work the forces took less the spring's gain: 0.037 % and
    // 0.057 %, against the 0.1 %
    check_test_scene_closes("block_overturn_record.toml", {});
}

TEST_CASE("a colonnade overturning along its row closes its energy balance as its columns fall onto each other", "[dem][energy]") {
    // two columns press side by side as they fall, the overlap of one's side ending on the edges
    // of the other's with depth. On a deformable target those edge forces acted at the point's
    // projection on the target plane while pushing along it: not a collinear pair, a couple that
    // made 27 J (0.13 % of the motion energy, the same at E 3e9 and 3e11 Pa and at any step).
    // Acting where the hitting point is: measured 0.041 % deformable, 0.041 % rigid, against the
    // issue's 0.1 %
    check_test_scene_closes("colonnade_overturn.toml", {});
}

TEST_CASE("a cube thrown tumbling onto a beam closes its energy balance as its faces turn past the beam's sides", "[dem][energy]") {
    // two throws, undamped. While the facing rule switched at n_h·n_o = −1e-3 a strip along an
    // edge between two target sides counted for one side, then for nobody: measured 1.0 % of the
    // motion energy rigid and deformable for the first throw, 0.44 % and 0.76 % for the second.
    // Blended (docs/dem.md, overlap scheme): 0.0044 / 0.0081 % and 0.015 / 0.030 %, against the
    // issue's 0.1 %
    check_test_scene_closes("cube_on_beam.toml", {});
    check_test_scene_closes("cube_on_beam.toml", {{"blocks.cube.position", "[-0.226, -0.166, 0.9]"},
                                                  {"blocks.cube.velocity", "[-0.21, 0.95, -1.0]"},
                                                  {"blocks.cube.angular_velocity", "[1.53, 5.37, 0.93]"}});
}

TEST_CASE("an arch collapsing under a pulse closes its energy balance as hinged voussoirs turn past the target rule's "
          "switch", "[dem][energy]") {
    // two equal voussoirs hinged 19° open keep their hitting and target sides while they touch: the
    // swap lost 14 J in one step, 3.4e-3 of the motion energy (now 1.9e-5); rigid only, the
    // deformable collapse takes minutes
    Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/tests/backends/dem/arch_collapse_pulse.toml");
    apply_model(s, "rigid");
    auto backend = dem_backend_info().make();
    const RunResult r = run_scene(*backend, s, RunOptions{});
    REQUIRE(r.status == RunStatus::completed);
    INFO("max balance error " << r.max_balance_error << " of the motion energy");
    CHECK(r.max_balance_error < kClosure);
}
