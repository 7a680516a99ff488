// every scene file shipped under scenarios/ loads and validates

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <filesystem>
#include <set>
#include <string>

#include "geometry/hexahedron.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

TEST_CASE("every shipped scene validates, and exactly the listed scenes ship", "[scene][scenarios]") {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(CAIRN_SOURCE_DIR) / "scenarios";
    std::set<std::string> found;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        if (e.path().extension() != ".toml") continue;
        if (*fs::relative(e.path(), root).begin() == "sweeps") continue;   // sweep plans, not scenes
        INFO(e.path().string());
        CHECK_NOTHROW(load_scene(e.path().string()));
        found.insert(fs::relative(e.path(), root).generic_string());
    }
    // the list docs/scenes.md and docs/validation.md describe: a scene added or lost shows here
    const std::set<std::string> shipped = {
        "earthquake/block_pulse_hold.toml", "earthquake/block_pulse_slide.toml",
        "earthquake/block_pulse_rock.toml", "earthquake/block_pulse_overturn.toml",
        "earthquake/column_elcentro.toml", "earthquake/frame_pulse_rock.toml", "earthquake/slope_pulse_slide.toml", "earthquake/stack_pulse_rock.toml", "paper/friction_slide.toml",  "paper/friction_stick.toml",
        "paper/friction_stick_base.toml",  "paper/impact.toml",          "paper/impact_damped.toml",
        "paper/rocking.toml",              "paper/rocking_damped_02.toml", "paper/rocking_damped_04.toml",
        "paper/rocking_housner.toml",      "paper/rocking_slender.toml", "paper/rocking_winkler.toml",
        "paper/rolling.toml",
        "paper/stability.toml",            "structures/arch.toml",       "structures/arch_thick.toml",
        "structures/arch_thin.toml",       "structures/column_pushover.toml", "structures/wall_pushover.toml"};
    CHECK(found == shipped);
}

namespace {
Scene paper(const std::string& name) {
    return load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/" + name + ".toml");
}
// lowest and highest z of a block's corners in the world at t = 0
std::pair<double, double> z_range(const BlockDef& b) {
    double lo = 1e300, hi = -1e300;
    for (const auto& c : b.corners) {
        double z = (b.position + b.orientation * c).z();
        lo = std::min(lo, z);
        hi = std::max(hi, z);
    }
    return {lo, hi};
}
}  // namespace

TEST_CASE("the paper scenes start A where docs/physics.md puts it", "[scene][scenarios]") {
    for (const char* name : {"stability", "friction_slide", "friction_stick", "friction_stick_base", "impact"}) {
        INFO(name);
        Scene s = paper(name);
        REQUIRE(s.block_index("A") == 0);
        REQUIRE(s.block_index("B") == 1);
        CHECK(s.blocks[1].fixed);
        CHECK(z_range(s.blocks[1]).second == Approx(0.0).margin(1e-12));   // B's top at z = 0
        // impact: a 0.10 m gap; friction: A starts at its static penetration m g/(kn A) so that
        // the undamped normal spring does not bounce; stability: released just touching
        const std::string n = name;
        const BlockDef& a = s.blocks[0];
        double m = mass_properties(a.corners, s.materials[a.material].density).mass;
        double start = n == "impact" ? 0.1 : n == "stability" ? 0.0 : -m * 9.81 / (s.contact.kn * 0.25);
        CHECK(z_range(a).first == Approx(start).margin(1e-8));
        CHECK(s.reference->block == 0);
        CHECK(std::any_of(s.probes.begin(), s.probes.end(), [](const ProbeDef& p) { return p.name == "node10"; }));
    }
}

TEST_CASE("the friction scenes push with H = 0.5 W of block A", "[scene][scenarios]") {
    for (const char* name : {"friction_slide", "friction_stick", "friction_stick_base"}) {
        Scene s = paper(name);
        const BlockDef& a = s.blocks[0];
        double m = mass_properties(a.corners, s.materials[a.material].density).mass;
        REQUIRE(s.loads.size() == 1);
        // the file writes H with all its digits: equal to 0.5 m g to rounding
        CHECK(s.loads[0].force.x() == Approx(0.5 * m * 9.81).epsilon(1e-12));
        CHECK(s.reference->values.at("force") == s.loads[0].force.x());
    }
    CHECK(paper("friction_slide").contact.friction == 0.4);
    CHECK(paper("friction_stick").contact.friction == 0.6);
    // the stick cases load slowly (8 s, 200 periods of the shear spring) on damped springs: the
    // references are quasi-static; H at the centroid, or at the centre of the base
    for (const char* name : {"friction_stick", "friction_stick_base"}) {
        Scene s = paper(name);
        CHECK(s.loads[0].ramp == 8.0);
        CHECK(s.contact.damping_rule == ContactDampingRule::ratio);
        CHECK(s.contact.damping == 0.5);
    }
    CHECK(paper("friction_stick").loads[0].point.z() == Approx(0.0).margin(1e-12));
    CHECK(paper("friction_stick_base").loads[0].point.z() == -0.25);
}

TEST_CASE("the rocking scenes stand on their +x edge, leaning back toward upright",
          "[scene][scenarios]") {
    struct Case { const char* name; double half_width; };
    for (Case c : {Case{"rocking", 0.35}, Case{"rocking_slender", 0.1}}) {
        INFO(c.name);
        Scene s = paper(c.name);
        const BlockDef& a = s.blocks[0];
        Vec3 com = a.position + a.orientation * mass_properties(a.corners, 2600).centre;
        // the two +x bottom corners (1, 2) rest on B's top at x = +half_width
        for (int i : {1, 2}) {
            Vec3 p = a.position + a.orientation * a.corners[i];
            CHECK(p.z() == Approx(0.0).margin(1e-12));
            CHECK(p.x() == Approx(c.half_width).margin(1e-12));
        }
        // the −x side is lifted and no corner is below B's top
        CHECK(z_range(a).first == Approx(0.0).margin(1e-12));
        CHECK((a.position + a.orientation * a.corners[0]).z() > 0.01);
        // centre of mass on the inner side of the pivot: gravity turns A back
        CHECK(com.x() < c.half_width);
        Eigen::AngleAxisd aa(a.orientation);
        CHECK(aa.angle() == Approx(s.reference->values.at("theta0")).epsilon(1e-12));
    }
}

TEST_CASE("the damped paper scenes differ from their undamped twins only by the damping ratio",
          "[scene][scenarios]") {
    struct Case { const char* name; const char* twin; double zeta; };
    for (Case c : {Case{"impact_damped", "impact", 0.1}, Case{"rocking_damped_02", "rocking", 0.2},
                   Case{"rocking_damped_04", "rocking", 0.4}}) {
        INFO(c.name);
        Scene s = paper(c.name), t = paper(c.twin);
        CHECK(s.contact.damping_rule == ContactDampingRule::ratio);
        CHECK(s.contact.damping == c.zeta);
        CHECK(t.contact.damping_rule == ContactDampingRule::none);
        CHECK(s.contact.kn == t.contact.kn);
        CHECK(s.blocks[0].position == t.blocks[0].position);
        CHECK(s.blocks[0].orientation.coeffs() == t.blocks[0].orientation.coeffs());
        CHECK(s.reference->values == t.reference->values);
    }
}

TEST_CASE("the rolling scene puts the cube's bottom face on the 45 degree face, centre above its downhill edge",
          "[scene][scenarios]") {
    Scene s = paper("rolling");
    const BlockDef& a = s.blocks[0];
    const BlockDef& b = s.blocks[1];
    REQUIRE(b.fixed);
    // B's top face (corners 4-7) is the slope z = 2.9698 − x, 1.0 m wide and 4.2 m long
    const double top = 4.2 * std::cos(M_PI / 4);
    for (int i = 4; i < 8; ++i) CHECK(b.corners[i].z() == Approx(top - b.corners[i].x()).margin(1e-9));
    CHECK((b.corners[5] - b.corners[4]).norm() == Approx(4.2).epsilon(1e-9));
    // A's four bottom corners lie on that plane
    for (int i = 0; i < 4; ++i) {
        Vec3 p = a.position + a.orientation * a.corners[i];
        CHECK(p.z() == Approx(top - p.x()).margin(1e-9));
        CHECK(p.x() > 0.0);
        CHECK(p.x() < top);
    }
    // neutral equilibrium: the centre of mass straight above the downhill bottom edge (corners 1, 2)
    Vec3 com = a.position + a.orientation * mass_properties(a.corners, 2600).centre;
    CHECK(com.x() == Approx((a.position + a.orientation * a.corners[1]).x()).margin(1e-9));
    CHECK(s.contact.friction > 1.0);   // > tan 45°: it cannot slide
    CHECK(s.reference->kind == "rolling");
}
