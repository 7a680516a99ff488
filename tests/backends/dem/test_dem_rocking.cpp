// A rigid block released tilted rocks about its edge; first impact against Housner (1963).
#include <catch2/catch.hpp>

#include <cmath>

#include "analytic/oracles.hpp"
#include "analytic/spring_block.hpp"
#include "scene/scene_io.hpp"
#include "dem_test_util.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

// block of width w (x) and depth d (y), height h, resting on its +x bottom edge, tilted theta0
// about y so that its centre of mass lies inside the edge; a fixed 2 x 2 x 1 m base
Scene rocking_scene(double w, double d, double h, double theta0, double kn) {
    Scene s = test::stone_scene(0.8);
    s.contact.kn = s.contact.ks = kn;
    s.contact.scheme = ContactScheme::paper;   // the paper's hitting points (overlap: test_dem_winkler_rocking)
    s.run.duration = 1.0;
    test::add_box_rotated_about(s, "A", Vec3(w, d, h), Vec3(0, 0, 0.5 * h), theta0, Vec3(0.5 * w, 0, 0), false);
    test::add_box(s, "B", Vec3(2, 2, 1), Vec3(0, 0, -0.5), true);
    return s;
}

// time at which the tilt about y first crosses zero, s (linear interpolation); -1 if never
double first_impact(Backend& b, double duration, double* min_tilt) {
    double t_prev = 0, th_prev = 0, hit = -1;
    *min_tilt = 0;
    test::run_dem(b, duration, [&](const Sample& s) {
        Eigen::AngleAxisd aa(s.blocks[0].orientation);
        double th = aa.angle() * aa.axis().y();
        if (hit < 0 && s.t > 0 && th_prev > 0 && th <= 0) hit = t_prev + th_prev / (th_prev - th) * (s.t - t_prev);
        *min_tilt = std::min(*min_tilt, th);
        t_prev = s.t;
        th_prev = th;
    });
    return hit;
}

}  // namespace

TEST_CASE("paper case (e), reading B: a 0.7 x 1.0 m block tilted 30 deg rocks about its edge", "[dem][rocking]") {
    oracle::HousnerBlock hb{0.35, 0.5, 9.81};
    const double theta0 = M_PI / 6;
    REQUIRE(hb.first_impact(theta0) == Approx(0.76160).epsilon(1e-4));
    for (double kn : {3e7, 3e8}) {
        auto b = test::build_dem(rocking_scene(0.7, 0.2, 1.0, theta0, kn));
        double min_tilt;
        double t1 = first_impact(*b, 1.2, &min_tilt);
        INFO("kn = " << kn << ", first impact " << t1 << " s");
        // docs/physics.md: a 2-D sketch of this case with 8 points across the 0.7 m face was +0.13 %
        // late at kn = 3e7 and within 0.02 % at 3e8; the issue allows 2 % for the DEM at the
        // paper's stiffness and closer as kn grows: 1 % and 0.5 % here
        CHECK(t1 == Approx(hb.first_impact(theta0)).epsilon(kn < 1e8 ? 0.01 : 0.005));
        // after the impact it rocks onto the other edge
        CHECK(min_tilt < -0.05);
    }
}

TEST_CASE("slender block (0.2 x 1.0 m) rocks with Housner's first impact at a stiff contact", "[dem][rocking]") {
    oracle::HousnerBlock hb{0.1, 0.5, 9.81};
    for (double frac : {0.5, 0.8}) {
        const double theta0 = frac * hb.alpha();
        auto b = test::build_dem(rocking_scene(0.2, 0.7, 1.0, theta0, 3e9));
        double min_tilt;
        double t1 = first_impact(*b, 0.8, &min_tilt);
        INFO("theta0 = " << frac << " alpha, first impact " << t1 << " s");
        // docs/physics.md: at kn = 3e9 a 2-D model was within 0.01 % for every grid; 0.5 % leaves
        // room for the 3-D block's edge springs and the sampling of the crossing
        CHECK(t1 == Approx(hb.first_impact(theta0)).epsilon(0.005));
    }
}

TEST_CASE("paper rocking scene: dem's rebound amplitudes follow the spring block on the same point springs",
          "[dem][rocking]") {
    // undamped penalty contact is not lossless for rocking (the block bounces and sways on the
    // springs and its edge slips at impact): the reference is the planar block on the scene's eight
    // rows of hitting points, with the same law, integrated by oracle::SpringBlock at T/1000
    Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/rocking.toml");
    const double th0 = s.reference->values.at("theta0");
    oracle::SpringBlock sb{0.7, 1.0, 0.7 * 0.2 * 1.0 * 2600.0, 9.81, s.contact.kn, s.contact.ks, s.contact.friction,
                           oracle::spring_rows(0.7, 0.2, 1, s.contact.grid_spacing)};
    const auto ref = sb.rock(th0, 3.0, 1e-3);
    REQUIRE(ref.amplitudes.size() >= 2);
    auto b = test::build_dem(s);
    double prev = th0, t_prev = 0.0, swing = 0.0;
    std::vector<double> impacts, amps;
    test::run_dem(*b, 3.0, [&](const Sample& x) {
        Eigen::AngleAxisd aa(x.blocks[0].orientation);
        const double th = aa.angle() * aa.axis().y();
        if ((prev > 0 && th <= 0) || (prev < 0 && th >= 0)) {
            impacts.push_back(t_prev + prev / (prev - th) * (x.t - t_prev));
            if (impacts.size() > 1) amps.push_back(swing);
            swing = 0.0;
        }
        if (!impacts.empty()) swing = std::max(swing, std::abs(th));
        prev = th;
        t_prev = x.t;
    });
    REQUIRE(amps.size() >= 2);
    // the amplitude is far from the lossless θ0 (−4 % after one impact, −45 % after two) ...
    CHECK(amps[1] < 0.6 * th0);
    // ... and within 2 % of the spring block's for the first two rebounds (measured 0.14 %, 0.16 %)
    for (size_t k = 0; k < 2; ++k) {
        INFO("rebound " << k + 1 << ": dem " << amps[k] << " rad, spring block " << ref.amplitudes[k] << " rad");
        CHECK(amps[k] == Approx(ref.amplitudes[k]).epsilon(0.02));
    }
}

TEST_CASE("rocking_housner scene: dem with the calibrated contact damping follows Housner for three impacts",
          "[dem][rocking]") {
    // ζ = 0.386 is where the spring block meets Housner's sequence for this block at kn = 3e7
    // (oracle::calibrate_housner_damping); dem on the same springs must follow
    Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/rocking_housner.toml");
    const double th0 = s.reference->values.at("theta0");
    const oracle::HousnerBlock hb{0.1, 0.5, 9.81};
    auto b = test::build_dem(s);
    double prev = th0, swing = 0.0;
    int crossings = 0;
    std::vector<double> amps;
    test::run_dem(*b, 3.0, [&](const Sample& x) {
        Eigen::AngleAxisd aa(x.blocks[0].orientation);
        const double th = aa.angle() * aa.axis().y();
        if ((prev > 0 && th <= 0) || (prev < 0 && th >= 0)) {
            if (++crossings > 1) amps.push_back(swing);
            swing = 0.0;
        }
        if (crossings > 0) swing = std::max(swing, std::abs(th));
        prev = th;
    });
    REQUIRE(amps.size() >= 3);
    for (int k = 0; k < 3; ++k) {
        INFO("impact " << k + 1 << ": dem " << amps[size_t(k)] << " rad, Housner " << hb.amplitude_after(th0, k + 1));
        // 2 %: the target for a calibrated contact, as for the amplitudes (measured −0.8 % to +0.7 %)
        CHECK(amps[size_t(k)] == Approx(hb.amplitude_after(th0, k + 1)).epsilon(0.02));
    }
}

TEST_CASE("paper rocking scene: the slip on impact is booked as the step does its work, so the balance closes to second order", "[dem][rocking][energy]") {
    // the block's edge slips at each impact; a slip booked as the cap's force times the slip
    // (first order: the spring's return to the cap each step went unbooked) left 4.48 J at
    // dt_safety 0.1 and 2.47 J at 0.05 of the 386 J the motion exchanges
    double residual[2], scale = 0.0;
    int i = 0;
    for (double safety : {0.1, 0.05}) {
        Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/rocking.toml",
                             {{"run.dt_safety", std::to_string(safety)}});
        auto b = test::build_dem(s);
        double e0 = 0.0, p0 = 0.0, p_min = 1e300;
        bool first = true;
        REQUIRE(test::run_dem(*b, s.run.duration, [&](const Sample& x) {
            if (first) e0 = x.energy.total(), p0 = x.energy.potential, first = false;
            p_min = std::min(p_min, x.energy.potential);
            residual[i] = x.energy.total() - e0;
        }));
        scale = p0 - p_min;   // the potential energy the motion exchanges
        ++i;
    }
    INFO("residual " << residual[0] << " J at dt_safety 0.1, " << residual[1] << " J at 0.05, motion energy " << scale << " J");
    REQUIRE(scale > 300.0);
    // the bar: within 0.1 % of the motion energy (measured 0.086 and 0.039 J)
    CHECK(std::abs(residual[0]) < 1e-3 * scale);
    CHECK(std::abs(residual[1]) < 1e-3 * scale);
    // and it falls faster than dt (measured ×2.2 for dt/2; first order gave ×1.8)
    CHECK(std::abs(residual[1]) < 0.5 * std::abs(residual[0]));
}
