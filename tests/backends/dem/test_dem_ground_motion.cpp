// Ground motion in the in-house engine: the inertial force −m·a_g(t) makes a block slide at the
// Coulomb rate and a slender block uplift at Housner's threshold a_g = g·tan(α).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "dem_test_util.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

namespace {

// a block of size (w, d, h) on a fixed 4 x 2 x 1 m base at its static penetration, with a ground
// acceleration along x given as inline samples (m/s²)
Scene shaken(double w, double d, double h, double mu, double kn, const std::string& times, const std::string& accel) {
    const double pen = 2600.0 * 9.81 * h / kn;   // m g/(kn A) with m = ρ w d h, A = w d
    std::string text = "[run]\nduration = 2.0\n[materials.stone]\ndensity = 2600\nyoung = 30e9\npoisson = 0.2\n"
                       "[contact]\nkn = " + std::to_string(kn) + "\nfriction = " + std::to_string(mu) +
                       "\n[blocks.A]\nsize = [" + std::to_string(w) + ", " + std::to_string(d) + ", " +
                       std::to_string(h) + "]\nposition = [0, 0, " + std::to_string(0.5 * h - pen) +
                       "]\nmaterial = \"stone\"\n[blocks.B]\nsize = [4, 2, 1]\nposition = [0, 0, -0.5]\n"
                       "material = \"stone\"\nfixed = true\n[ground_motion]\ntime = " + times +
                       "\nacceleration = " + accel + "\nunits = \"m/s2\"\n";
    return parse_scene(text, "<ground motion test>");
}

double tilt_about_y(const Quat& q) {
    Eigen::AngleAxisd aa(q);
    return aa.angle() * aa.axis().y();
}

}  // namespace

TEST_CASE("a ground acceleration of 0.6 g slides a block at (0.6 - mu) g relative to the ground", "[dem][ground]") {
    const double ag = 0.6 * 9.81;
    Scene s = shaken(0.5, 0.5, 0.5, 0.4, 3e7, "[0, 10]", "[" + std::to_string(ag) + ", " + std::to_string(ag) + "]");
    auto b = test::build_dem(s);
    // least-squares s(t) = c0 + c1 t + a t²/2 from 0.2 s (after the shear springs load up)
    Eigen::Matrix3d n = Eigen::Matrix3d::Zero();
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    test::run_dem(*b, 1.0, [&](const Sample& x) {
        if (x.t < 0.2) return;
        Eigen::Vector3d basis(1.0, x.t, 0.5 * x.t * x.t);
        n += basis * basis.transpose();
        r += basis * x.blocks[0].position.x();
    });
    // in the ground's frame the block feels −m·a_g against friction μ·m·g: a = −(0.6 − 0.4) g;
    // 1 % as for the pulled block (the same Coulomb law, the same fit)
    CHECK(n.ldlt().solve(r)[2] == Approx(-0.2 * 9.81).epsilon(0.01));
}

TEST_CASE("a slender block uplifts once the ground acceleration passes g·tan(alpha)", "[dem][ground]") {
    // b/h = 0.1/0.5: the threshold is 0.2 g. The acceleration is ramped over 1 s so that the
    // contact springs follow quasi-statically (a sudden step would overshoot and uplift early)
    for (double ratio : {0.9, 1.2}) {
        const double amax = ratio * 0.2 * 9.81;
        Scene s = shaken(0.2, 0.7, 1.0, 0.8, 3e9, "[0, 1, 10]",
                         "[0, " + std::to_string(amax) + ", " + std::to_string(amax) + "]");
        // the paper's edge rows lift at the rigid threshold; a Winkler joint (the overlap scheme)
        // starts to lift its heel at a third of it and leans before it tips
        s.contact.scheme = ContactScheme::paper;
        auto b = test::build_dem(s);
        double worst = 0.0;
        test::run_dem(*b, 1.6, [&](const Sample& x) { worst = std::max(worst, std::abs(tilt_about_y(x.blocks[0].orientation))); });
        INFO("peak a_g = " << ratio << " g tan(alpha), largest tilt " << worst << " rad");
        if (ratio < 1.0) {
            // below the threshold only the stiff contact's elastic tilt: M/(kn·I_A) ≈ 1e-5 rad
            CHECK(worst < 1e-3);
        } else {
            // above it the block rocks up on its edge within the 0.6 s after the ramp
            CHECK(worst > 0.05);
        }
    }
}
