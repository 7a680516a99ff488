// A hitting point (paper scheme) or sub-contact (overlap scheme) that enters or leaves contact
// inside a step: the step's work on the block is the spring energy it stores or gives back.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "dem_test_util.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

constexpr double kDt = 1e-4;        // s: ω·dt ≈ 0.03 for the 0.1 m cube on kn = 3e7
constexpr double kSpeed = 1.0;      // m/s: the cube moves kSpeed·kDt = 0.1 mm in a step
constexpr double kEdge = 0.1;       // m

// a free 0.1 m cube A over a fixed 0.2 m cube B (top at z = 0), no gravity, no friction work (it
// moves along the normal only); bottom face of A at z = gap, moving at vz; paper: the grid is
// the 4 corners of the face
Scene drop(ContactScheme scheme, double gap, double vz) {
    Scene s = test::stone_scene();
    s.gravity = Vec3::Zero();
    s.contact.scheme = scheme;
    s.contact.grid_spacing = 0.2;
    s.run.dt = kDt;
    test::add_box(s, "A", Vec3(kEdge, kEdge, kEdge), Vec3(0, 0, 0.5 * kEdge + gap), false);
    test::add_box(s, "B", Vec3(0.2, 0.2, 0.2), Vec3(0, 0, -0.1), true);
    s.blocks[0].velocity = Vec3(0, 0, vz);
    return s;
}

}  // namespace

TEST_CASE("a face entering contact inside a step books exactly the spring energy it stores", "[dem][energy][contact]") {
    for (auto scheme : {ContactScheme::paper, ContactScheme::overlap}) {
        for (double phi : {0.2, 0.5, 0.9}) {
            INFO("scheme " << int(scheme) << ", part of the step in contact " << phi);
            // the gap closes at (1 − φ)·dt: the face is φ·v·dt deep at the end of the step
            const double gap = (1.0 - phi) * kSpeed * kDt;
            auto b = test::build_dem(drop(scheme, gap, -kSpeed));
            const Energies e0 = b->sample().energy;
            REQUIRE(b->step() == StepStatus::ok);
            const Energies e1 = b->sample().energy;
            const double m = 2600.0 * std::pow(kEdge, 3), k = 3e7 * kEdge * kEdge;   // kg, N/m
            const double d1 = phi * kSpeed * kDt;
            CHECK(e1.contact == Approx(0.5 * k * d1 * d1).epsilon(1e-9));
            // the step pushes with φ·k·d1 in its end half kick: its trapezoid work is
            // ½·φ·k·d1·(v·dt) = ½k·d1², the stored energy; the step's kinetic energy leaves out
            // the end half kick's (dt²/8)·F²/m (docs/dem.md, Energy), so the balance does not move:
            // 1e-3 of that term (~3e-11 J) is far above the round-off of the cube's 1.3 J
            const double f_end = phi * k * d1;
            const double shadow = kDt * kDt / 8.0 * f_end * f_end / m;
            CHECK(std::abs(e1.total() - e0.total()) < 1e-3 * shadow);
            // the step's force alone (the whole k·d1 at the end) would have taken ½k·d1·gap more
            // out of the kinetic energy than the spring stores: 4 to 900 times the shadow here
            CHECK(0.5 * k * d1 * gap > 4.0 * shadow);
        }
    }
}

TEST_CASE("a face leaving contact inside a step gets back exactly the spring energy it stored", "[dem][energy][contact]") {
    for (auto scheme : {ContactScheme::paper, ContactScheme::overlap}) {
        for (double phi : {0.2, 0.5, 0.9}) {
            INFO("scheme " << int(scheme) << ", part of the step in contact " << phi);
            const double m = 2600.0 * std::pow(kEdge, 3), k = 3e7 * kEdge * kEdge;   // kg, N/m
            // start d0 deep moving up at v: the first half kick adds k·d0·dt/(2m), and the step's
            // drift of v_half·dt takes the face to d1 = d0 − v_half·dt; choose d0 so that the gap
            // opens after the part φ of the step: d0 = φ·v_half·dt
            const double d0 = phi * kSpeed * kDt / (1.0 - phi * k * kDt * kDt / (2.0 * m));
            const double v_half = kSpeed + k * d0 * kDt / (2.0 * m);
            REQUIRE(d0 == Approx(phi * v_half * kDt).epsilon(1e-12));
            auto b = test::build_dem(drop(scheme, -d0, kSpeed));
            const Energies e0 = b->sample().energy;
            CHECK(e0.contact == Approx(0.5 * k * d0 * d0).epsilon(1e-9));
            REQUIRE(b->step() == StepStatus::ok);
            const Energies e1 = b->sample().energy;
            CHECK(e1.contact == 0.0);
            // first half kick k·d0, end half kick (φ − 1)·k·d0: the trapezoid work is
            // ½·φ·k·d0·v_half·dt = ½k·d0², the energy given back; ½mv² would carry
            // (dt²/8)·(F_end² − F_start²)/m, which the step's kinetic energy leaves out at both ends
            const double f0 = k * d0, f_end = (phi - 1.0) * k * d0;
            const double shadow = kDt * kDt / 8.0 * (f_end * f_end - f0 * f0) / m;
            CHECK(std::abs(e1.total() - e0.total()) < 1e-3 * std::abs(shadow));
            CHECK(0.5 * k * d0 * (1.0 - phi) * v_half * kDt > 4.0 * std::abs(shadow));
        }
    }
}

TEST_CASE("a column toppling onto its side books its dashpots' work through the lift-off", "[dem][energy][contact]") {
    // a 0.3 × 0.3 × 1.5 m column released on its edge past its tipping angle (0.25 rad against
    // atan(0.3/1.5) = 0.197) falls over and lands on its long side with 2100 J, and its side lifts
    // off again at an angle within a few steps. Where the side pulls away faster than its springs
    // relax, the dashpot cancels the spring (the force is clipped at zero): its work is then minus
    // the spring's exact energy change. It was booked by the trapezoid of its force, which for the
    // shrinking wedge of a lifting face (U = ½kn∫d² dA goes as its depth cubed) is more: the
    // balance moved by 3.18 J at ζ = 0.05 and 3.48 J at ζ = 0.2 (1.5e-3 and 1.7e-3 of the peak
    // kinetic energy), now 0.11 J and 0.17 J. 2e-4 of the peak kinetic energy: what is left is the
    // springs' own trapezoid work on that wedge (undamped, 1.05 J, second order in dt: docs/dem.md)
    for (double zeta : {0.05, 0.2}) {
        Scene s = test::stone_scene(0.7);
        s.contact.kn = s.contact.ks = 3e9;
        s.contact.scheme = ContactScheme::overlap;
        s.contact.damping_rule = ContactDampingRule::ratio;
        s.contact.damping = zeta;
        test::add_box(s, "B", Vec3(6.0, 6.0, 0.5), Vec3(0, 0, -0.25), true);
        test::add_box_rotated_about(s, "A", Vec3(0.3, 0.3, 1.5), Vec3(0, 0, 0.75), 0.25, Vec3(0.15, 0, 0), false);
        auto b = test::build_dem(s);
        const double e0 = b->sample().energy.total();
        double worst = 0.0, peak = 0.0, lowest = 1e9;
        REQUIRE(test::run_dem(*b, 1.45, [&](const Sample& smp) {
            worst = std::max(worst, std::abs(smp.energy.total() - e0));
            peak = std::max(peak, smp.energy.kinetic);
            lowest = std::min(lowest, smp.blocks[0].position.z());
        }));
        INFO("zeta " << zeta << ": largest balance error " << worst << " J, peak kinetic energy " << peak << " J");
        REQUIRE(lowest < 0.16);   // it fell onto its side (centre 0.15 m above the base)
        CHECK(worst < 2e-4 * peak);
    }
}
