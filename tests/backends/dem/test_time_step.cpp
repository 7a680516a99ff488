// The contact springs' critical step of a free cube resting on one side, against the closed forms
// of its spring-mass modes, the elements' critical step of a deformable cube against its
// dilatational mode, and the backend's automatic step (the safety factor times it).
#include <catch2/catch.hpp>

#include <cmath>

#include "dem/block_builder.hpp"
#include "dem/time_step.hpp"
#include "scene/scene_io.hpp"
#include "scene/tower_builder.hpp"
#include "support/scene_builder.hpp"
#include "dem_test_util.hpp"

using namespace cairn;

namespace {

// eigenvalues from a symmetric eigensolver: relative round-off of a few ulp of the largest entry
constexpr double kEigenTol = 1e-12;

constexpr double kEdge = 0.5;                       // m
constexpr double kArea = kEdge * kEdge;             // m²
constexpr double kMass = 2600.0 * kEdge * kEdge * kEdge;   // kg, the stone's density

// a scene with one free cube of edge kEdge (and a fixed base under it when `base`)
Scene cube_scene(ContactScheme scheme, double kn, double ks, bool base = false) {
    Scene s = test::stone_scene();
    s.contact.scheme = scheme;
    s.contact.kn = kn;
    s.contact.ks = ks;
    add_box(s, "A", Vec3(kEdge, kEdge, kEdge), Vec3(0, 0, 0.5 * kEdge), false);
    if (base) add_box(s, "base", Vec3(1, 1, 0.5), Vec3(0, 0, -0.25), true);
    return s;
}

dem::Block cube(const Scene& s) { return dem::make_block(s.blocks[0], s); }

// largest squared frequency of a cube on one side with springs kn = ks = k (per unit area),
// integrated exactly over the side: vertical k·A/m, torsion k·A/m, and sliding coupled to
// rocking (lever h = edge/2 of the shear springs, I = m·edge²/6) whose larger root is
// (k·A/m)·(3 + √7)/2
double cube_omega2_equal_springs(double k) { return k * kArea / kMass * (3.0 + std::sqrt(7.0)) / 2.0; }

}  // namespace

TEST_CASE("dem time step: a side's normal springs give the vertical spring-mass frequency", "[dem][time_step]") {
    // ks = 0: the normal springs alone; vertical k·A/m, rocking k·(edge⁴/12)/(m·edge²/6) = k·A/(2m)
    const double kn = 3e7;
    const Scene s = cube_scene(ContactScheme::overlap, kn, 0.0);
    const auto b = cube(s);
    for (int side = 0; side < 6; ++side)
        CHECK(dem::side_contact_omega2(b, side, s.contact) == Approx(kn * kArea / kMass).epsilon(kEigenTol));
}

TEST_CASE("dem time step: sliding and rocking couple through the shear springs' lever", "[dem][time_step]") {
    const double k = 3e7;
    const Scene s = cube_scene(ContactScheme::overlap, k, k);
    const auto b = cube(s);
    CHECK(dem::side_contact_omega2(b, 0, s.contact) == Approx(cube_omega2_equal_springs(k)).epsilon(kEigenTol));
}

TEST_CASE("dem time step: the paper scheme's corner springs stiffen rocking", "[dem][time_step]") {
    // a grid spacing above the edge leaves the 4 corners, A/4 each: Σ x²·dA = A·edge²/4 instead
    // of edge⁴/12, so rocking k·A·(edge²/4)/(m·edge²/6) = 1.5·k·A/m passes the vertical mode
    const double kn = 3e7;
    Scene s = cube_scene(ContactScheme::paper, kn, 0.0);
    s.contact.grid_spacing = 2.0 * kEdge;
    const auto b = cube(s);
    CHECK(dem::hit_grid(b.side_quad(0), s.contact.grid_spacing).size() == 4);
    CHECK(dem::side_contact_omega2(b, 0, s.contact) == Approx(1.5 * kn * kArea / kMass).epsilon(kEigenTol));
}

TEST_CASE("dem time step: the critical step is 2/omega, less for damping", "[dem][time_step]") {
    const double k = 3e7;
    Scene s = cube_scene(ContactScheme::overlap, k, k);
    const double w = std::sqrt(cube_omega2_equal_springs(k));
    std::vector<dem::Block> blocks{cube(s)};
    CHECK(dem::contact_critical_step(blocks, s.contact) == Approx(2.0 / w).epsilon(kEigenTol));

    // ζ = 0.2 of critical: 2/ω·(√(1+ζ²) − ζ)
    s.contact.damping_rule = ContactDampingRule::ratio;
    s.contact.damping = 0.2;
    CHECK(dem::contact_critical_step(blocks, s.contact) ==
          Approx(2.0 / w * (std::sqrt(1.04) - 0.2)).epsilon(kEigenTol));

    // dashpot γ = 1e-4 s: ζ = γ·ω/2
    s.contact.damping_rule = ContactDampingRule::time;
    s.contact.damping = 1e-4;
    const double zeta = 0.5 * 1e-4 * w;
    CHECK(dem::contact_critical_step(blocks, s.contact) ==
          Approx(2.0 / w * (std::sqrt(1.0 + zeta * zeta) - zeta)).epsilon(kEigenTol));
}

TEST_CASE("dem time step: a pair of free blocks sums their squared frequencies, fixed blocks count none", "[dem][time_step]") {
    // two equal blocks on springs in series: the pair's frequency is at most √2 times one's
    const double k = 3e7;
    const Scene s = cube_scene(ContactScheme::overlap, k, k, true);
    const double w = std::sqrt(cube_omega2_equal_springs(k));
    std::vector<dem::Block> one{cube(s), dem::make_block(s.blocks[1], s)};
    CHECK(one[1].fixed);
    CHECK(dem::contact_critical_step(one, s.contact) == Approx(2.0 / w).epsilon(kEigenTol));
    std::vector<dem::Block> two{cube(s), cube(s)};
    CHECK(dem::contact_critical_step(two, s.contact) == Approx(2.0 / (std::sqrt(2.0) * w)).epsilon(kEigenTol));
    CHECK(dem::contact_critical_step({one[1]}, s.contact) == 0.0);   // nothing free: no step
    CHECK(dem::element_critical_step(two) == 0.0);                   // no deformable block
}

TEST_CASE("dem time step: run.dt = auto takes the safety factor times the critical step", "[dem][time_step]") {
    const double k = 3e7;
    Scene s = cube_scene(ContactScheme::overlap, k, k, true);
    s.run.dt.reset();
    s.run.dt_safety = 0.1;
    const double crit = 2.0 / std::sqrt(cube_omega2_equal_springs(k));
    auto backend = test::build_dem(s);
    CHECK(backend->critical_step() == Approx(crit).epsilon(kEigenTol));
    CHECK(backend->time_step() == Approx(0.1 * crit).epsilon(kEigenTol));
}

TEST_CASE("dem time step: a lumped hex8 cube's critical step is its uniform dilatation's", "[dem][time_step]") {
    // one fully integrated hex8 of edge L with lumped mass ρL³/8 per corner: the highest mode is
    // the uniform expansion u = ε·x (strain energy ½ε²(9λ+6μ)L³, corners moving ε·L·√3/2), so
    // ω² = 4(3λ+2μ)/(ρL²) and Δt = 2/ω = (L/c_d)·√((λ+2μ)/(3λ+2μ)), c_d = √((λ+2μ)/ρ) the
    // dilatational wave speed; at ν = 0.2 (λ = 2μ/3) that is √(2/3)·L/c_d
    for (const double nu : {0.2, 0.3}) {
        Scene s = cube_scene(ContactScheme::overlap, 3e7, 3e7);
        s.materials[0].poisson = nu;
        s.blocks[0].model = BlockModel::deformable;
        s.blocks[0].mesh.mass = MassScheme::lumped;
        const Material& m = s.materials[0];
        const double lambda = m.young * nu / ((1 + nu) * (1 - 2 * nu)), mu = m.young / (2 * (1 + nu));
        const double c_d = std::sqrt((lambda + 2 * mu) / m.density);
        const double expected = kEdge / c_d * std::sqrt((lambda + 2 * mu) / (3 * lambda + 2 * mu));
        if (nu == 0.2) CHECK(expected == Approx(std::sqrt(2.0 / 3.0) * kEdge / c_d).epsilon(1e-14));
        std::vector<dem::Block> blocks{cube(s)};
        REQUIRE(blocks[0].deformable);
        // a generalised eigensolver of a 24 x 24 pair: a few ulp of the largest eigenvalue
        CHECK(dem::element_critical_step(blocks) == Approx(expected).epsilon(kEigenTol));
        // stiffness damping β: ζ = β·ω/2 lowers it to 2/ω·(√(1+ζ²) − ζ)
        s.damping.beta = 1e-5;
        std::vector<dem::Block> damped{cube(s)};
        const double w = 2.0 / expected, zeta = 0.5 * 1e-5 * w;
        CHECK(dem::element_critical_step(damped) == Approx(2.0 / w * (std::sqrt(1.0 + zeta * zeta) - zeta)).epsilon(kEigenTol));
    }
}

TEST_CASE("dem time step: only blocks within reach pair up, apart, each is a mass on its springs", "[dem][time_step]") {
    // ks = 0 on the overlap scheme: a cube's stiffest mode is the vertical k = kn·A on mass m,
    // so alone on a base its critical step is the closed form 2·√(m/k); two free cubes on each
    // other form springs in series of equal masses, ω² = 2k/m, so 2·√(m/2k)
    const double kn = 3e7, k = kn * kArea;
    const double alone = 2.0 * std::sqrt(kMass / k), paired = 2.0 * std::sqrt(kMass / (2.0 * k));
    Scene stacked = test::stone_scene();
    stacked.contact.scheme = ContactScheme::overlap;
    stacked.contact.kn = kn;
    stacked.contact.ks = 0.0;
    Scene apart = stacked;
    add_box(stacked, "A", Vec3(kEdge, kEdge, kEdge), Vec3(0, 0, 0.5 * kEdge), false);
    add_box(stacked, "B", Vec3(kEdge, kEdge, kEdge), Vec3(0, 0, 1.5 * kEdge), false);
    add_box(stacked, "base", Vec3(1, 1, 0.5), Vec3(0, 0, -0.25), true);
    // two cubes 2 m apart, each on its own base: no pair within reach
    add_box(apart, "A", Vec3(kEdge, kEdge, kEdge), Vec3(0, 0, 0.5 * kEdge), false);
    add_box(apart, "B", Vec3(kEdge, kEdge, kEdge), Vec3(2, 0, 0.5 * kEdge), false);
    add_box(apart, "baseA", Vec3(1, 1, 0.5), Vec3(0, 0, -0.25), true);
    add_box(apart, "baseB", Vec3(1, 1, 0.5), Vec3(2, 0, -0.25), true);
    for (Scene* s : {&stacked, &apart}) s->run.dt.reset();
    CHECK(test::build_dem(stacked)->critical_step() == Approx(paired).epsilon(kEigenTol));
    CHECK(test::build_dem(apart)->critical_step() == Approx(alone).epsilon(kEigenTol));
    // without a reach every two free blocks pair up (the bound before blocks were located)
    std::vector<dem::Block> blocks;
    for (const auto& def : apart.blocks) blocks.push_back(dem::make_block(def, apart));
    CHECK(dem::contact_critical_step(blocks, apart.contact) == Approx(paired).epsilon(kEigenTol));
    CHECK(dem::contact_critical_step(blocks, apart.contact, 0.05 * kEdge) == Approx(alone).epsilon(kEigenTol));
}

TEST_CASE("dem time step: the paper's scenes keep the step of the all-pairs bound", "[dem][time_step]") {
    // each holds one free block, or free blocks that touch: the stiffest pair is within reach
    for (const char* name : {"friction_slide", "friction_stick", "friction_stick_base", "impact", "impact_damped",
                             "rocking", "rocking_damped_02", "rocking_damped_04", "rocking_housner", "rocking_slender",
                             "rolling", "stability"}) {
        INFO(name);
        Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/" + name + ".toml", {});
        std::vector<dem::Block> blocks;
        for (const auto& def : s.blocks) blocks.push_back(dem::make_block(def, s));
        s.run.dt.reset();
        CHECK(test::build_dem(s)->critical_step() == Approx(dem::contact_critical_step(blocks, s.contact)).epsilon(kEigenTol));
    }
}

TEST_CASE("dem time step: a tower of equal bricks keeps the all-pairs step", "[dem][time_step]") {
    // every brick of `cairn make tower` has the same stiffest side and touches an equal one,
    // so the stiffest pair within reach is the pair of the two largest values anywhere
    Scene s = test::stone_scene();
    s.contact.scheme = ContactScheme::overlap;
    s.contact.subdivision = 1;
    TowerSpec t;
    t.length = t.width = 4;
    t.courses = 6;
    add_tower(s, t);
    std::vector<dem::Block> blocks;
    for (const auto& def : s.blocks) blocks.push_back(dem::make_block(def, s));
    const double all_pairs = dem::contact_critical_step(blocks, s.contact);
    s.run.dt.reset();
    CHECK(test::build_dem(s)->critical_step() == Approx(all_pairs).epsilon(kEigenTol));
}
