// The torsion spring of an overlap sub-contact: the disc's constants, the spin it measures, the
// couple it applies and the energy it books.
#include <catch2/catch.hpp>

#include <cmath>

#include "dem/block_builder.hpp"
#include "dem/contact_twist.hpp"
#include "dem/face.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;
using namespace cairn::dem;

namespace {

constexpr double kPi = 3.14159265358979323846;

// the boundary face of block b whose outward normal is `n`
int face_along(const Block& b, const Vec3& n) {
    for (int k = 0; k < int(b.mesh.faces.size()); ++k)
        if (quad_normal(b.face_quad(k), Vec2::Zero()).dot(n) > 0.999) return k;
    return -1;
}

// a 1 m cube A on a fixed slab B, A spinning about z at `spin` (rad/s) and moving along x at 1 m/s
struct Pair {
    Scene scene = test::stone_scene(0.5);
    std::vector<Block> blocks;
    int hit = -1, target = -1;   ///< A's bottom face, B's top face
    explicit Pair(double spin) {
        test::add_box(scene, "A", Vec3(1, 1, 1), Vec3(0.1, 0.2, 0.5), false);
        test::add_box(scene, "B", Vec3(3, 3, 0.5), Vec3(0, 0, -0.25), true);
        for (const auto& d : scene.blocks) blocks.push_back(make_block(d, scene));
        // a rigid block moves as its body: the node velocities follow (v + ω × arm from the centre)
        blocks[0].body.v = Vec3(1, 0, 0);
        blocks[0].body.set_omega(Vec3(0, 0, spin));
        blocks[0].update_nodes();
        hit = face_along(blocks[0], -Vec3::UnitZ());
        target = face_along(blocks[1], Vec3::UnitZ());
    }
};

// a sub-contact of A's bottom on B's top touching for the first time
TwistInput first_touch(double area, double normal_force, const Vec3& centroid) {
    TwistInput in;
    in.area = area;
    in.normal_force = normal_force;
    in.centroid = centroid;
    in.normal = Vec3::UnitZ();
    in.lay = true;
    return in;
}

}  // namespace

TEST_CASE("twist: a disc's polar moment and friction radius", "[dem][contact][twist]") {
    // a disc of radius R: J = πR⁴/2, mean distance from its centre 2R/3
    const double r = 0.3, area = kPi * r * r;
    CHECK(disc_polar_moment(area) == Approx(kPi * std::pow(r, 4) / 2).epsilon(1e-14));
    CHECK(disc_friction_radius(area) == Approx(2 * r / 3).epsilon(1e-14));
}

TEST_CASE("twist: the spring measures the relative spin, and its couple is a pure moment about the normal",
          "[dem][contact][twist]") {
    Pair p(2.0);
    Block& a = p.blocks[0];
    Block& b = p.blocks[1];
    REQUIRE(p.hit >= 0);
    REQUIRE(p.target >= 0);
    TwistInput in = first_touch(0.04, 1e6, Vec3(0.3, 0.1, 0.0));   // a sub-cell off the spin axis
    in.edge = Vec3(1, 1, 0);
    const TwistLaw law{1e9, 0.5, 0.0, true};
    SubTwist tw;
    ContactTotals tot;
    const double dt = 1e-4;
    update_twist(tw, in, law, a, p.hit, b, p.target, dt, tot);
    // the translation along x does not enter: the spin is A's angular velocity about z
    CHECK(twist_spin(tw, a, b) == Approx(2.0).epsilon(1e-12));
    const double kt = 1e9 * 0.04 * 0.04 / (2 * kPi);
    CHECK(tw.moment == Approx(-kt * 2.0 * dt).epsilon(1e-12));
    CHECK(tot.stored == Approx(0.5 * kt * std::pow(2.0 * dt, 2)).epsilon(1e-12));
    // the couple: no net force, a moment M·n about any point
    for (auto& blk : p.blocks) std::fill(blk.f.begin(), blk.f.end(), Vec3::Zero());
    add_twist_forces(tw, in.normal, nullptr, a, b);
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
    for (size_t i = 0; i < a.x.size(); ++i) force += a.f[i], moment += a.x[i].cross(a.f[i]);
    CHECK(force.norm() < 1e-12 * std::abs(tw.moment));
    CHECK((moment - tw.moment * Vec3::UnitZ()).norm() < 1e-9 * std::abs(tw.moment));
    Vec3 target_moment = Vec3::Zero();
    for (size_t i = 0; i < b.x.size(); ++i) target_moment += b.x[i].cross(b.f[i]);
    CHECK((target_moment + tw.moment * Vec3::UnitZ()).norm() < 1e-9 * std::abs(tw.moment));
}

TEST_CASE("twist: past the friction cap the spring slips and books the work it took",
          "[dem][contact][twist]") {
    Pair p(50.0);
    Block& a = p.blocks[0];
    Block& b = p.blocks[1];
    TwistInput in = first_touch(0.04, 100.0, Vec3(0.1, 0.2, 0.0));
    in.shear_force = 30.0;   // 0.6 of μ·F_n: the moment keeps √(1 − 0.36) = 0.8 of its cap
    const TwistLaw law{1e9, 0.5, 0.0, true};
    SubTwist tw;
    ContactTotals tot;
    const double dt = 1e-4;
    update_twist(tw, in, law, a, p.hit, b, p.target, dt, tot);
    const double cap = 0.5 * 100.0 * disc_friction_radius(0.04) * 0.8;
    CHECK(tw.moment == Approx(-cap).epsilon(1e-12));
    // the trapezoid's work of the moment against the spin, less what the spring kept
    const double kept = 0.5 * cap * cap / (1e9 * disc_polar_moment(0.04));
    CHECK(tot.stored == Approx(kept).epsilon(1e-12));
    CHECK(tot.dissipated == Approx(0.5 * dt * cap * 50.0 - kept).epsilon(1e-12));
    // released: what it kept is dissipated, less the work of its last moment over the step
    ContactTotals after;
    release_twist(tw, a, b, dt, after);
    CHECK(after.dissipated == Approx(kept + 0.5 * dt * cap * 50.0).epsilon(1e-12));
    CHECK(tw.moment == 0.0);
}
