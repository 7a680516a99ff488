// the case analyses on synthetic runs whose answers are known by construction (not the oracles'
// own curves): each metric must measure the built-in value, and its verdict must be the one the
// built-in error against the reference gives
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "analytic/oracles.hpp"
#include "analytic/spring_block.hpp"
#include "analytic/winkler_block.hpp"
#include "cases/case_analysis.hpp"
#include "cases/case_kind.hpp"
#include "cases/case_util.hpp"
#include "cases/winkler_model.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

namespace {

Scene paper(const std::string& name) {
    return load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/" + name + ".toml");
}

/// samples every dt of block A and every probe moved by `d(t)` (world), A turned by θ(t) about y
std::vector<Sample> run_of(const Scene& s, double duration, double dt, const std::function<Vec3(double)>& d,
                           const std::function<double(double)>& theta = nullptr) {
    std::vector<Sample> out;
    const long n = std::lround(duration / dt);
    for (long i = 0; i <= n; ++i) {
        const double t = double(i) * dt;
        Sample x;
        x.t = t;
        for (const auto& p : s.probes) {
            const BlockDef& b = s.blocks[size_t(p.block)];
            x.probes.push_back(b.position + b.orientation * p.point + d(t));
        }
        BlockState b;
        b.position = s.blocks[0].position + d(t);
        b.orientation = theta ? Quat(Eigen::AngleAxisd(theta(t), Vec3::UnitY())) : s.blocks[0].orientation;
        x.blocks.push_back(b);
        out.push_back(x);
    }
    return out;
}

const metrics::Metric& find(const cases::CaseAnalysis& a, const std::string& name) {
    for (const auto& m : a.metrics)
        if (m.name == name) return m;
    FAIL("no metric " << name);
    return a.metrics.front();
}

}  // namespace

TEST_CASE("stability: a swing of chosen depth and period is measured and judged", "[cases]") {
    Scene s = paper("stability");
    oracle::RestingBlock rb{2600.0, 3e7, 9.81};
    const double eq = rb.penetration();
    // released just touching, any swing is d(t) = A (1 − cos 2πt/P) from the start
    auto judge = [&](double A, double P) {
        return cases::analyse_case(s, run_of(s, 0.5, 1e-4, [&](double t) { return Vec3(0, 0, -A * (1 - std::cos(2 * M_PI * t / P))); }),
                                   {true});
    };
    // depth −0.5 % (pass at 1 %), period +2 % (miss)
    const double A = 0.995 * eq, P = 1.02 * rb.period();
    auto a = judge(A, P);
    // 1e-4: samples every 1e-4 s of a 60 ms swing (the sampled peak is low by (π dt/P)²/2 = 1.4e-5)
    CHECK(find(a, "equilibrium penetration").value == Approx(A).epsilon(1e-4));
    CHECK(find(a, "peak penetration").value == Approx(2 * A).epsilon(1e-4));
    CHECK(find(a, "period").value == Approx(P).epsilon(1e-4));
    CHECK(std::string(find(a, "equilibrium penetration").verdict()) == "pass");
    CHECK(std::string(find(a, "peak penetration").verdict()) == "pass");
    CHECK(std::string(find(a, "period").verdict()) == "miss");
    // depth −2 %: both penetrations miss; the exact period passes
    auto b = judge(0.98 * eq, rb.period());
    CHECK(std::string(find(b, "equilibrium penetration").verdict()) == "miss");
    CHECK(std::string(find(b, "peak penetration").verdict()) == "miss");
    CHECK(std::string(find(b, "period").verdict()) == "pass");
}

TEST_CASE("impact: a built bounce of known touch, depth, period and rebound", "[cases]") {
    Scene s = paper("impact");
    const double gap = 0.1, g = 9.81;
    oracle::DampedDrop o{2600.0, 3e7, 0.0, g, gap};
    const auto b = o.first_bounce();
    // touch 2 % late (miss at 1 %), depth 1 % shallow (pass at 2 %), the oracle's contact time and
    // a rebound to 1.01 e² of the gap (pass at 2 %)
    const double tc = 1.02 * std::sqrt(2 * gap / g), fall_g = 2 * gap / (tc * tc);
    const double depth = 0.99 * b.max_penetration, tau = b.contact_time;
    const double apex = 1.01 * b.restitution * b.restitution * gap, vr = std::sqrt(2 * g * apex);
    const double t2 = tc + tau + 2 * vr / g;
    auto h = [&](double t) {
        if (t < tc) return gap - 0.5 * fall_g * t * t;
        if (t < tc + tau) return -depth * std::sin(M_PI * (t - tc) / tau);
        if (t < t2) return vr * (t - tc - tau) - 0.5 * g * (t - tc - tau) * (t - tc - tau);
        return -depth * std::sin(M_PI * std::min(1.0, (t - t2) / tau));
    };
    auto run = run_of(s, 0.7, 1e-5, [&](double t) { return Vec3(0, 0, h(t) - gap); });
    auto a = cases::analyse_case(s, run, {true});
    CHECK(find(a, "first contact").value == Approx(tc).epsilon(1e-5));
    CHECK(find(a, "peak penetration").value == Approx(depth).epsilon(1e-5));
    CHECK(find(a, "bounce period").value == Approx(t2 - tc).epsilon(1e-5));
    CHECK(find(a, "rebound ratio").value == Approx(apex / gap).epsilon(1e-5));
    CHECK(std::string(find(a, "first contact").verdict()) == "miss");
    CHECK(std::string(find(a, "peak penetration").verdict()) == "pass");
    // the bounce period's flight part is 2 e v0 √1.01 / g: +0.4 % of the period, within 1 %
    CHECK(std::string(find(a, "bounce period").verdict()) == "pass");
    CHECK(std::string(find(a, "rebound ratio").verdict()) == "pass");
}

namespace {

/// θ(t): from θ0 at rest a quarter cosine to the first crossing at t1, then half sines of the given
/// amplitudes and half cycles (alternating sign)
std::function<double(double)> rocking_path(double th0, double t1, std::vector<double> amps, std::vector<double> halves) {
    return [=](double t) {
        if (t < t1) return th0 * std::cos(0.5 * M_PI * t / t1);
        double start = t1, sign = -1.0;
        for (size_t k = 0; k < amps.size(); ++k) {
            if (t < start + halves[k]) return sign * amps[k] * std::sin(M_PI * (t - start) / halves[k]);
            start += halves[k];
            sign = -sign;
        }
        return 0.0;
    };
}

}  // namespace

TEST_CASE("rocking: a built history judged against Housner (rigid), the spring block (dem) and nothing (matched)",
          "[cases]") {
    Scene s = paper("rocking");
    oracle::HousnerBlock hb{0.35, 0.5, 9.81};
    const double th0 = s.reference->values.at("theta0");
    const double dt = 1e-4;

    SECTION("rigid contact: Housner") {
        // first impact +0.5 % (pass at 1 %), amplitude +5 % (miss at 2 %), half cycle −0.5 % of 2 t1(θ1)
        const double t1 = 1.005 * hb.first_impact(th0), a1 = 1.05 * hb.amplitude_after(th0, 1);
        const double h1 = 0.995 * 2 * hb.first_impact(a1), a2 = 0.02, h2 = 0.3;
        auto run = run_of(s, 3.0, dt, [](double) { return Vec3::Zero(); }, rocking_path(th0, t1, {a1, a2}, {h1, h2}));
        auto a = cases::analyse_case(s, run, {false});
        CHECK(find(a, "first impact").value == Approx(t1).epsilon(1e-5));
        CHECK(find(a, "amplitude after 1st impact").value == Approx(a1).epsilon(1e-6));
        // 1e-4: the second crossing is interpolated linearly across the kink between two half sines
        CHECK(find(a, "half cycle (1st to 2nd impact)").value == Approx(h1).epsilon(1e-4));
        CHECK(std::string(find(a, "first impact").verdict()) == "pass");
        CHECK(std::string(find(a, "amplitude after 1st impact").verdict()) == "miss");
        CHECK(std::string(find(a, "impact velocity ratio").verdict()) == "miss");
        // judged with the measured θ1: the amplitude miss does not make the half cycle miss
        CHECK(std::string(find(a, "half cycle (1st to 2nd impact)").verdict()) == "pass");
    }
    SECTION("dem's point springs: the spring block") {
        oracle::SpringBlock sb{0.7, 1.0, 364.0, 9.81, 3e7, 3e7, 0.8, oracle::spring_rows(0.7, 0.2, 1, 0.1)};
        const auto ref = sb.rock(th0, 3.0, 1e-3);
        REQUIRE(ref.amplitudes.size() >= 2);
        // amplitudes −1 % (pass) and +3 % (miss) of the spring block's
        const double t1 = ref.impacts[0], a1 = 0.99 * ref.amplitudes[0], a2 = 1.03 * ref.amplitudes[1];
        const double h1 = 2 * hb.first_impact(a1), h2 = 2 * hb.first_impact(a2);
        auto run = run_of(s, 3.0, dt, [](double) { return Vec3::Zero(); }, rocking_path(th0, t1, {a1, a2, 0.05}, {h1, h2, 0.5}));
        auto a = cases::analyse_case(s, run, {true});
        CHECK(find(a, "amplitude after 1st impact").reference == Approx(ref.amplitudes[0]).epsilon(1e-4));
        CHECK(std::string(find(a, "first impact").verdict()) == "pass");
        CHECK(std::string(find(a, "amplitude after 1st impact").verdict()) == "pass");
        CHECK(std::string(find(a, "amplitude after 2nd impact").verdict()) == "miss");
        CHECK(std::string(find(a, "half cycle (1st to 2nd impact)").verdict()) == "pass");
        // energy closure: nothing drifts in these samples; 2 % of the rocking energy booked nowhere misses
        CHECK(std::string(find(a, "energy closure").verdict()) == "pass");
        const double rock = 364.0 * 9.81 * hb.radius() * (std::cos(hb.alpha() - th0) - std::cos(hb.alpha()));
        run.back().energy.kinetic = 0.02 * rock;
        CHECK(std::string(find(cases::analyse_case(s, run, {true}), "energy closure").verdict()) == "miss");
    }
    SECTION("dem's overlap contact on a soft base: the Winkler base's half cycle, not Housner's") {
        // the slender block (0.2 m wide) at kn 1e9: its edge sinks in on every swing, and the
        // Winkler base's half cycle is 9 % longer than Housner's 2 t1(θ1) at the same amplitude
        Scene sl = paper("rocking_slender");
        sl.contact.scheme = ContactScheme::overlap;
        sl.contact.kn = sl.contact.ks = 1e9;
        oracle::HousnerBlock slender{0.1, 0.5, 9.81};
        const double th = sl.reference->values.at("theta0");
        const auto ref = cases::winkler_model(sl, {true}, Vec3::UnitY()).rock(th, 3.0, 1e-4);
        REQUIRE(ref.crossings.size() >= 2);
        const double t1 = ref.crossings[0], a1 = ref.amplitudes[0], h1 = ref.crossings[1] - ref.crossings[0];
        REQUIRE(h1 > 1.05 * 2 * slender.first_impact(a1));   // the case this section is about
        auto judge = [&](double half) {
            auto run = run_of(sl, 3.0, dt, [](double) { return Vec3::Zero(); }, rocking_path(th, t1, {a1, 0.01}, {half, 0.3}));
            return find(cases::analyse_case(sl, run, {true}), "half cycle (1st to 2nd impact)");
        };
        CHECK(judge(h1).reference == Approx(h1).epsilon(1e-3));
        CHECK(std::string(judge(h1).verdict()) == "pass");
        CHECK(std::string(judge(1.03 * h1).verdict()) == "miss");
    }
    SECTION("a deformable block soft against its joints: its swings after an impact are shown, not judged") {
        // the slender block at kn 1e9 and E 3e10 Pa: kn·h/E = 0.033, past the 0.005 below which a
        // deformable block rocks as the rigid one (docs/validation.md, "A flexible block rocking")
        Scene sl = paper("rocking_slender");
        sl.contact.scheme = ContactScheme::overlap;
        sl.contact.kn = sl.contact.ks = 1e9;
        CHECK(cases::joint_to_block_stiffness(sl, sl.reference->block) == Approx(1e9 * 1.0 / 30e9));
        const double th = sl.reference->values.at("theta0");
        cases::ContactKind deformable;
        deformable.deformable = true;
        deformable.divisions = sl.blocks.at(size_t(sl.reference->block)).mesh.divisions;
        const auto ref = cases::winkler_model(sl, deformable, Vec3::UnitY()).rock(th, 3.0, 1e-4);
        REQUIRE(ref.crossings.size() >= 2);
        // the first swing 30 % short, as a flexible pillar's (a miss for a rigid block)
        const double t1 = ref.crossings[0], a1 = 0.7 * ref.amplitudes[0], h1 = ref.crossings[1] - ref.crossings[0];
        auto run = run_of(sl, 3.0, dt, [](double) { return Vec3::Zero(); }, rocking_path(th, t1, {a1, 0.01}, {h1, 0.3}));
        auto a = cases::analyse_case(sl, run, deformable);
        CHECK(std::string(find(a, "amplitude after 1st impact").verdict()) == "info");
        CHECK(find(a, "amplitude after 1st impact").reference == Approx(ref.amplitudes[0]).epsilon(1e-3));
        CHECK_THAT(find(a, "amplitude after 1st impact").basis, Catch::Matchers::Contains("kn·h/E = 0.0333"));
        CHECK(std::string(find(a, "half cycle (1st to 2nd impact)").verdict()) == "info");
        // the same block ten times stiffer (E 3e11 Pa: kn·h/E = 0.0033) is judged, and misses
        sl.materials.at(size_t(sl.blocks.at(size_t(sl.reference->block)).material)).young = 3e11;
        const auto stiff = cases::analyse_case(sl, run, deformable);
        CHECK(std::string(find(stiff, "amplitude after 1st impact").verdict()) == "miss");
        // and the rigid variant of the soft block is judged whatever kn·h/E
        sl.materials.at(size_t(sl.blocks.at(size_t(sl.reference->block)).material)).young = 3e10;
        cases::ContactKind rigid_block;
        const auto rigid = cases::analyse_case(sl, run, rigid_block);
        CHECK(std::string(find(rigid, "amplitude after 1st impact").verdict()) == "miss");
    }
    SECTION("an engine's matched contact: no reference after the first impact") {
        const double t1 = hb.first_impact(th0), a1 = 0.05;
        auto run = run_of(s, 3.0, dt, [](double) { return Vec3::Zero(); },
                          rocking_path(th0, t1, {a1, 0.01}, {2 * hb.first_impact(a1), 0.3}));
        cases::ContactKind matched;
        matched.point_springs = false;
        auto a = cases::analyse_case(s, run, matched);
        CHECK(std::string(find(a, "first impact").verdict()) == "pass");
        CHECK(std::string(find(a, "amplitude after 1st impact").verdict()) == "not comparable");
        CHECK(std::string(find(a, "half cycle (1st to 2nd impact)").verdict()) == "not comparable");
        CHECK_THAT(find(a, "amplitude after 1st impact").basis, Catch::Matchers::Contains("matched"));
    }
}

TEST_CASE("rocking: the tilt is measured from the upright block in any world", "[cases]") {
    // reading B's history, then the scene and its history turned whole: gravity along −y (turned about
    // x), along −x (turned about the rocking axis itself) and along a skew axis. Each is measured from
    // its own upright block; measured from the world's axes, the turn about the rocking axis added
    // its 90° to θ, and the block "never came back upright"
    const Scene s = paper("rocking");
    oracle::HousnerBlock hb{0.35, 0.5, 9.81};
    const double th0 = s.reference->values.at("theta0");
    const double t1 = hb.first_impact(th0), a1 = hb.amplitude_after(th0, 1), h1 = 2 * hb.first_impact(a1);
    const auto run = run_of(s, 3.0, 1e-4, [](double) { return Vec3::Zero(); }, rocking_path(th0, t1, {a1, 0.02}, {h1, 0.3}));
    const auto flat = cases::analyse_case(s, run, {false});
    for (const auto& [axis, angle] : {std::pair<Vec3, double>{Vec3::UnitX(), -M_PI / 2}, {Vec3::UnitY(), M_PI / 2},
                                      {Vec3(1, 1, 1).normalized(), 2.0}}) {
        const Quat r(Eigen::AngleAxisd(angle, axis));
        Scene turned = s;
        turned.gravity = r * s.gravity;
        for (auto& b : turned.blocks) b.position = r * b.position, b.orientation = r * b.orientation;
        const Vec3 a = r * cases::rocking_axis(s);
        turned.reference->values["axis_x"] = a.x();
        turned.reference->values["axis_y"] = a.y();
        turned.reference->values["axis_z"] = a.z();
        auto moved = run;
        for (auto& x : moved)
            for (auto& b : x.blocks) b.position = r * b.position, b.orientation = r * b.orientation;
        const auto same = cases::analyse_case(turned, moved, {false});
        INFO("turned " << angle << " rad about (" << axis.transpose() << ")");
        for (const char* m : {"first impact", "amplitude after 1st impact", "half cycle (1st to 2nd impact)"}) {
            INFO(m);
            // 1e-9: the same history, turned and turned back in double precision
            CHECK(find(same, m).value == Approx(find(flat, m).value).epsilon(1e-9));
        }
    }
}

TEST_CASE("rolling: a cube tumbling down the slope is judged alike in any world", "[cases]") {
    // a built tumble (turning about y, moving down the slope) of the shipped scene, then the scene and
    // its history turned about the vertical, into a Y-up world and about a skew axis: the oracle's
    // frame puts gravity along −z and the fall line along +x again, so every metric is the same
    const Scene s = paper("rolling");
    const double slope = s.reference->values.at("slope");
    const Vec3 down(std::cos(slope), 0.0, -std::sin(slope));
    const auto run = run_of(s, 2.0, 1e-3, [&](double t) { return Vec3(0.7 * t * down); },
                            [&](double t) { return slope + 1.6 * t; });
    const auto flat = cases::analyse_case(s, run, {false});
    REQUIRE(flat.metrics.size() >= 4);
    for (const auto& [axis, angle] : {std::pair<Vec3, double>{Vec3::UnitZ(), 1.0}, {Vec3::UnitX(), -M_PI / 2},
                                      {Vec3(1, 2, 3).normalized(), 2.5}}) {
        const Quat r(Eigen::AngleAxisd(angle, axis));
        INFO("turned " << angle << " rad about (" << axis.transpose() << ")");
        const Scene turned = cases::turned_scene(s, r);
        CHECK_NOTHROW(cases::case_kind("rolling", turned.source).check(turned));
        const auto same = cases::analyse_case(turned, cases::turned_samples(run, r), {false});
        REQUIRE(same.metrics.size() == flat.metrics.size());
        for (size_t k = 0; k < flat.metrics.size(); ++k) {
            INFO(flat.metrics[k].name);
            // 1e-9 relative, 1e-12 absolute: the same history, turned and turned back
            CHECK(same.metrics[k].value == Approx(flat.metrics[k].value).epsilon(1e-9).margin(1e-12));
        }
    }
}

TEST_CASE("friction_stick: a built base displacement judged against the Winkler block", "[cases]") {
    Scene s = paper("friction_stick");
    const double W = 325.0 * 9.81, H = s.reference->values.at("force");
    oracle::WinklerBlock wb{0.5, 0.5, 3e7, 3e7, 0.6, W};
    wb.com_height = 0.25;   // the weight follows the tilt: 0.6 % more than the 4.0249e-4 m without
    const double u_ref = wb.shear_displacement(H, 0.25), ramp = s.loads[0].ramp, T = s.run.duration;
    REQUIRE(u_ref == Approx(4.0496e-4).epsilon(1e-4));
    // u follows the ramp to u_end, then holds (plus a creep of `creep` over the hold)
    auto judge = [&](double u_end, double creep) {
        auto run = run_of(s, T, 1e-3, [&](double t) {
            return Vec3(t < ramp ? u_end * t / ramp : u_end + creep * (t - ramp) / (T - ramp), 0, 0);
        });
        return cases::analyse_case(s, run, {true});
    };
    auto a = judge(1.02 * u_ref, 0.0);   // +2 %: pass at 3 %
    // the mean over the second half of the hold: exactly u_end
    CHECK(find(a, "base shear displacement").value == Approx(1.02 * u_ref).epsilon(1e-9));
    CHECK(std::string(find(a, "base shear displacement").verdict()) == "pass");
    CHECK(std::string(find(a, "slip while held").verdict()) == "pass");
    auto b = judge(1.05 * u_ref, 0.0);   // +5 %: miss
    CHECK(std::string(find(b, "base shear displacement").verdict()) == "miss");
    // a creep of 20 % of u over the 2 s hold: 10 % over the judged second half, beyond 5 %
    auto c = judge(u_ref, 0.2 * u_ref);
    CHECK(find(c, "slip while held").value == Approx(0.1 * u_ref).epsilon(1e-6));
    CHECK(std::string(find(c, "slip while held").verdict()) == "miss");
    // ringing by ±8 % of u over the hold (0.3 s swings), as a block rocking on part of its base:
    // no drift is read into it, and its mean is not taken for the static state
    auto ringing = [&](double creep) {
        auto run = run_of(s, T, 1e-3, [&](double t) {
            const double hold = t < ramp ? 0.0 : 0.08 * u_ref * std::sin(2 * M_PI * (t - ramp) / 0.3);
            return Vec3((t < ramp ? u_ref * t / ramp : u_ref + creep * (t - ramp) / (T - ramp)) + hold, 0, 0);
        });
        return cases::analyse_case(s, run, {true});
    };
    auto d = ringing(0.0);
    CHECK(std::abs(find(d, "slip while held").value) < 1e-3 * u_ref);
    CHECK(std::string(find(d, "slip while held").verdict()) == "pass");
    CHECK(std::string(find(d, "base shear displacement").verdict()) == "info");
    CHECK_THAT(find(d, "base shear displacement").basis, Catch::Contains("still rings"));
    auto e = ringing(0.2 * u_ref);
    CHECK(find(e, "slip while held").value == Approx(0.1 * u_ref).epsilon(1e-2));
    CHECK(std::string(find(e, "slip while held").verdict()) == "miss");
    // a ramp of 1 s, 5.5 periods of the block's rocking on its springs (0.181 s): not quasi-static
    Scene fast = s;
    fast.loads[0].ramp = 1.0;
    auto f = cases::analyse_case(fast, run_of(fast, T, 1e-3, [&](double t) { return Vec3(u_ref * std::min(t, 1.0), 0, 0); }), {true});
    CHECK_THAT(find(f, "base shear displacement").basis, Catch::Contains("not slow"));
    CHECK(std::string(find(f, "base shear displacement").verdict()) == "info");
    // a 0.15 m grid puts 2.5 hitting points across the 0.373 m contact zone: its slip is not resolved
    Scene coarse = s;
    coarse.contact.grid_spacing = 0.15;
    auto g = judge(u_ref, 0.0);
    CHECK(std::string(find(g, "base shear displacement").verdict()) == "pass");
    auto run = run_of(coarse, T, 1e-3, [&](double t) { return Vec3(t < ramp ? u_ref * t / ramp : u_ref, 0, 0); });
    auto h = cases::analyse_case(coarse, run, {true});
    CHECK_THAT(find(h, "base shear displacement").basis, Catch::Contains("fewer than three"));
}

TEST_CASE("newmark hold: a record that ends within the second half is judged on the rest after it", "[cases]") {
    // earthquake/block_pulse_hold run to 1.2 s: its 0.45 g pulse ends at 0.701 s, past half the
    // run. Built runs: the block swings with the pulse by up to ±0.4 µm, unevenly (the record's
    // envelope), then rests. The judged window is the second half of the time after the pulse,
    // where a held block lies still, and a creep there is read
    Scene s = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/earthquake/block_pulse_hold.toml");
    s.run.duration = 1.2;
    const double T = s.run.duration;
    auto judge = [&](double creep_rate) {   // m/s, after the pulse
        auto run = run_of(s, T, 1e-3, [&](double t) {
            double x = 0.0;
            if (t > 0.2 && t < 0.701) x = 4e-7 * std::sin(2 * M_PI * 9.0 * t) * std::sin(M_PI * (t - 0.2) / 0.501);
            if (t >= 0.701) x = creep_rate * (t - 0.701);
            return Vec3(x, 0, 0);
        });
        return cases::analyse_case(s, run, {true});
    };
    const auto still = judge(0.0);
    const auto& held = find(still, "slip while held");
    INFO(held.basis);
    CHECK(std::abs(held.value) < 1e-12);
    CHECK(std::string(held.verdict()) == "pass");
    CHECK_THAT(held.basis, Catch::Contains("after the drive's end at 0.701 s"));
    // a creep of 1 µm/s after the pulse: 0.25 µm over the 0.25 s window, far past 5 % of the
    // elastic base shear (m·0.45 g/(ks·A) = 4.6 µm: 0.23 µm)
    const auto creeping = judge(1e-6);
    // (read along the drive's push, −x: the creep along +x reads negative)
    CHECK(find(creeping, "slip while held").value == Approx(-1e-6 * 0.2495).epsilon(1e-2));
    CHECK(std::string(find(creeping, "slip while held").verdict()) == "miss");
}

TEST_CASE("a deformable block compliant against its joints is shown, not judged, by the sliding kinds", "[cases]") {
    // stick: paper case (c) with a stone 50 times softer, ks·h/G = 0.06 above 0.05: its own shear
    // would add about 0.7 % to its base's, which the rigid block on springs leaves out. The same
    // built run, at the oracle's answer, is judged for a rigid block and shown for a deformable one
    Scene s = paper("friction_stick");
    s.materials.at(size_t(s.blocks.at(size_t(s.reference->block)).material)).young /= 50.0;
    const double W = 325.0 * 9.81, H = s.reference->values.at("force");
    oracle::WinklerBlock wb{0.5, 0.5, 3e7, 3e7, 0.6, W};
    wb.com_height = 0.25;
    const double u_ref = wb.shear_displacement(H, 0.25), ramp = s.loads[0].ramp;
    const auto run = run_of(s, s.run.duration, 1e-3, [&](double t) { return Vec3(t < ramp ? u_ref * t / ramp : u_ref, 0, 0); });
    cases::ContactKind rigid_block, deformable_block;
    deformable_block.deformable = true;
    CHECK(cases::joint_to_block_shear(s, s.reference->block) == Approx(0.06).epsilon(1e-9));
    CHECK(std::string(find(cases::analyse_case(s, run, rigid_block), "base shear displacement").verdict()) == "pass");
    const auto shown = find(cases::analyse_case(s, run, deformable_block), "base shear displacement");
    CHECK(std::string(shown.verdict()) == "info");
    CHECK_THAT(shown.basis, Catch::Contains("compliant in shear against its joints (ks·h/G = 0.06"));

    // newmark: earthquake/block_pulse_slide with kn·h/E = 1.33, above 1: a built run at the oracle's
    // slide is judged for a rigid block, shown for a deformable one, every metric
    Scene p = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/earthquake/block_pulse_slide.toml");
    p.materials.at(size_t(p.blocks.at(size_t(p.reference->block)).material)).young = p.contact.kn * 0.4 / (4.0 / 3.0);
    REQUIRE(cases::joint_to_block_stiffness(p, p.reference->block) == Approx(4.0 / 3.0).epsilon(1e-9));
    const auto& kind = cases::case_kind("newmark", p.source);
    std::vector<double> t;
    for (int i = 0; i <= 2000; ++i) t.push_back(1e-3 * i * p.run.duration / 2.0);
    const auto slide = kind.curve(p, {}, t);
    const auto built = run_of(p, p.run.duration, 1e-3, [&](double at) {
        return Vec3(-metrics::interpolate(metrics::Series{t, slide}, at), 0, 0);   // along the push, −x
    });
    const auto judged = cases::analyse_case(p, built, rigid_block);
    const auto shown_all = cases::analyse_case(p, built, deformable_block);
    REQUIRE(judged.metrics.size() == shown_all.metrics.size());
    int was_judged = 0;
    for (size_t k = 0; k < judged.metrics.size(); ++k) {
        INFO(judged.metrics[k].name << ": " << judged.metrics[k].basis);
        if (!judged.metrics[k].judged()) continue;
        ++was_judged;
        CHECK(judged.metrics[k].pass());
        CHECK(std::string(shown_all.metrics[k].verdict()) == "info");
        CHECK(shown_all.metrics[k].value == judged.metrics[k].value);
        CHECK_THAT(shown_all.metrics[k].basis, Catch::Contains("compliant against its joints (kn·h/E = 1.33"));
    }
    CHECK(was_judged == 2);   // the largest and the final slide
}
