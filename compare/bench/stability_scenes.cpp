// the points of the stability map: a scene per parameter value and the oracle that judges it
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analytic/oracles.hpp"
#include "bench/stability.hpp"
#include "cases/case_analysis.hpp"
#include "cases/case_util.hpp"
#include "error.hpp"
#include "output/number_format.hpp"
#include "metrics/signal.hpp"
#include "scene/scene_io.hpp"

namespace cairn::bench {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string g(double v) { return number_format("%g", v); }

Scene load(const std::string& path, const std::vector<std::string>& sets) {
    std::vector<Override> o;
    for (const auto& s : sets) o.push_back(parse_override(s));
    return load_scene(path, o);
}

/// every metric of the scene's own case analysis must pass (compare/cases tolerances)
Judgement all_metrics(const Scene& scene, const std::vector<Sample>& s, bool penalty,
                      const std::vector<std::string>& only = {}) {
    if (s.size() < 3) return {false, "too few samples"};
    std::string fails, passes;
    for (const auto& m : cases::analyse_case(scene, s, {penalty}).metrics) {
        if (!only.empty() && std::find(only.begin(), only.end(), m.name) == only.end()) continue;
        char b[200];
        std::snprintf(b, sizeof b, "%s %.4g vs %.4g (%s)", m.name.c_str(), m.value, m.reference, m.tolerance_text().c_str());
        std::string& to = m.pass() ? passes : fails;
        to += (to.empty() ? "" : "; ") + std::string(b);
    }
    return {fails.empty(), fails.empty() ? passes : "MISS " + fails};
}

/// height of block A's bottom above the contact plane from its centre (no rotation): start height + gap
metrics::Series bottom_height(const Scene& scene, const std::vector<Sample>& s, double gap) {
    auto h = cases::com_series(s, cases::free_index(scene, scene.reference->block), 2, true);
    for (double& y : h.y) y += gap;
    return h;
}

/// a two-block stack on a fixed base, placed at its static penetrations: lower block A (2600
/// kg/m³), upper block C of `ratio` times A's density, 1 m cubes, kn = 3e9 N/m³
Scene stack_scene(double ratio) {
    const double kn = 3e9, g0 = 9.81, m = 2600.0, mc = m * ratio;
    const double d1 = (m + mc) * g0 / kn, d2 = mc * g0 / kn;   // A = 1 m²
    std::string t = "description = \"stack, mass ratio " + g(ratio) + "\"\n[run]\nduration = 0.3\n"
                    "[materials.stone]\ndensity = 2600\nyoung = 30e9\npoisson = 0.2\n"
                    "[materials.top]\ndensity = " + g(2600.0 * ratio) + "\nyoung = 30e9\npoisson = 0.2\n"
                    "[contact]\nkn = 3e9\nks = 3e9\nfriction = 0.6\n"
                    "[blocks.A]\nsize = [1.0, 1.0, 1.0]\nposition = [0.0, 0.0, " + g(0.5 - d1) + "]\nmaterial = \"stone\"\n"
                    "[blocks.C]\nsize = [1.0, 1.0, 1.0]\nposition = [0.0, 0.0, " + g(1.5 - d1 - d2) + "]\nmaterial = \"top\"\n"
                    "[blocks.B]\nsize = [2.0, 2.0, 1.0]\nposition = [0.0, 0.0, -0.5]\nmaterial = \"stone\"\nfixed = true\n"
                    "[reference]\nkind = \"rest\"\nblock = \"A\"\n";
    Scene s = parse_scene(t, "<stack " + g(ratio) + ">");
    s.run.output_interval = 1e-3;
    return s;
}

/// a stack holds when no block moves more than the stack's static compression d1 + d2 (the oracle:
/// placed at equilibrium, an exact penalty model does not move at all)
Judgement stack_judge(const Scene& scene, const std::vector<Sample>& s) {
    const int a = scene.block_index("A"), c = scene.block_index("C");
    const double mc = cases::block_mass(scene, c), d1 = (cases::block_mass(scene, a) + mc) * 9.81 / 3e9;
    const double bound = d1 + mc * 9.81 / 3e9;
    double worst = 0.0;
    for (const auto& x : s) {
        worst = std::max(worst, (x.blocks.at(size_t(cases::free_index(scene, a))).position - scene.blocks[size_t(a)].position).norm());
        worst = std::max(worst, (x.blocks.at(size_t(cases::free_index(scene, c))).position - scene.blocks[size_t(c)].position).norm());
    }
    char b[160];
    std::snprintf(b, sizeof b, "largest block displacement %.3g m vs the static compression %.3g m", worst, bound);
    return {worst <= bound, b};
}

}  // namespace

std::vector<StabilityConfig> stability_configs(const std::string& backend, const std::string& dir,
                                               const std::vector<BackendInfo>& backends, long long long_steps) {
    const BackendInfo& info = find_backend(backends, backend);
    const bool dem = info.contact == ContactModel::penalty;
    const std::string matched = dem ? "rigid" : "matched";
    // a rigid-contact engine with no spring stand-in (no penalty stiffness in its capability row)
    // has no matched mode
    const bool springs = dem || support_of(info, Feature::penalty_stiffness) != Support::none;
    std::vector<StabilityConfig> out;
    auto add = [&](const std::string& param, const std::string& text, double value, Scene scene,
                   const std::string& mode, auto judge) {
        if (mode == "matched" && !springs) return;
        StabilityConfig c;
        c.point.backend = backend;
        c.point.parameter = param;
        c.point.value_text = text;
        c.point.value = value;
        c.point.energy_booked = dem || mode == "matched";
        c.scene = std::move(scene);
        c.contact_mode = mode;
        c.judge = judge;
        out.push_back(std::move(c));
    };
    const std::string rest = dir + "/paper/stability.toml", impact = dir + "/paper/impact.toml";
    const bool penalty = true;
    // contact stiffness: a 1 m cube released touching, one period of its contact spring at least
    for (double kn = 1e5; kn < 2e12; kn *= 10.0) {
        Scene s = load(rest, {"contact.kn=" + g(kn), "contact.ks=" + g(kn)});
        const double T = 2.0 * kPi * std::sqrt(2600.0 / kn);
        s.run.duration = std::max(0.2, 1.3 * T);
        s.run.output_interval = std::min(1e-3, T / 50.0);
        add("kn", g(kn), kn, s, matched, [=](const Scene& sc, const std::vector<Sample>& x) { return all_metrics(sc, x, penalty); });
    }
    // time step: the impact case; dem at multiples of its critical step, the engines over their range
    auto impact_scene = [&] {
        Scene s = load(impact, {"run.duration=0.5"});
        s.run.output_interval = 1e-4;
        return s;
    };
    if (dem) {
        Scene probe = impact_scene();
        auto b = find_backend(backends, "dem").make();
        b->build(probe, RunOptions{});
        const double crit = b->critical_step();
        for (double f : {0.1, 0.2, 0.5, 1.0, 1.5, 2.0, 3.0, 5.0}) {   // 3, 5: where it really blows up
            Scene s = impact_scene();
            s.run.dt = f * crit;
            add("dt", g(f) + " crit", f, s, "rigid", [](const Scene& sc, const std::vector<Sample>& x) { return all_metrics(sc, x, true); });
        }
    } else {
        for (double dt : {1e-5, 1e-4, 1e-3, 3e-3, 1e-2}) {
            Scene s = impact_scene();
            s.run.dt = dt;
            add("dt", g(dt) + " s", dt, s, "matched", [](const Scene& sc, const std::vector<Sample>& x) { return all_metrics(sc, x, true); });
        }
    }
    // mass ratio of a two-block stack placed at its static penetrations
    for (double r : {1e-3, 1e-2, 1e-1, 1.0, 1e1, 1e2, 1e3})
        add("mass ratio", g(r), r, stack_scene(r), matched, stack_judge);
    // friction: the pulled block of case (c), H = 0.5 W applied at once
    for (double mu : {0.0, 0.2, 0.4, 0.6, 1.0, 2.0}) {
        Scene s = load(dir + "/paper/friction_slide.toml", {"contact.friction=" + g(mu), "run.duration=0.5"});
        add("friction", g(mu), mu, s, "rigid", [](const Scene& sc, const std::vector<Sample>& x) {
            const int a = sc.reference->block;
            const double m = cases::block_mass(sc, a), H = sc.reference->values.at("force");
            const double acc = oracle::pulled_block_acceleration(m, cases::gravity(sc), H, sc.contact.friction);
            auto c = metrics::polyfit(cases::com_series(x, cases::free_index(sc, a), 0, true), 2, 0.1 * x.back().t, x.back().t);
            const double meas = 2.0 * c[2], tol = 0.02 * H / m;
            char b[160];
            std::snprintf(b, sizeof b, "acceleration %.4g vs %.4g m/s² (± %.3g: 2 %% of H/m)", meas, acc, tol);
            return Judgement{std::abs(meas - acc) <= tol, b};
        });
    }
    // slenderness: a 1 m tall block, 2b = tan α, released at θ0 = α/2 on its edge, kn = 3e9
    for (double deg : {1.0, 2.0, 5.0, 10.0, 20.0, 30.0, 45.0}) {
        const double a = deg * kPi / 180.0, b = 0.5 * std::tan(a), th0 = 0.5 * a;
        Scene s = load(dir + "/paper/rocking_slender.toml",
                       {"contact.kn=3e9", "contact.ks=3e9", "blocks.A.size=[" + g(2 * b) + ",0.7,1.0]",
                        "blocks.A.orientation={axis=[0.0,1.0,0.0],angle=" + g(th0) + "}",
                        "blocks.A.pivot=[" + g(b) + ",0.0,0.0]", "reference.theta0=" + g(th0)});
        const oracle::HousnerBlock hb{b, 0.5, 9.81};
        s.run.duration = 1.3 * hb.first_impact(th0) + 0.05;
        s.run.output_interval = 2e-4;
        add("alpha", g(deg) + "°", deg, s, "rigid", [dem](const Scene& sc, const std::vector<Sample>& x) {
            return all_metrics(sc, x, dem, {"first impact"});
        });
    }
    // impact speed: A 1 mm above B moving down at v (kn = 3e7 as the paper)
    for (double v : {0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0}) {
        Scene s = load(impact, {"blocks.A.position=[0.0,0.0,0.501]", "blocks.A.velocity=[0.0,0.0,-" + g(v) + "]"});
        const double m = 2600.0, K = s.contact.kn * 1.0, gap = 1e-3;
        const oracle::DampedDrop drop{m, K, 0.0, 9.81, gap + v * v / (2.0 * 9.81)};
        const auto bounce = drop.first_bounce();
        s.run.duration = gap / v + 1.5 * bounce.contact_time + 5e-3;
        s.run.output_interval = std::min(1e-4, bounce.contact_time / 200.0);
        add("impact speed", g(v) + " m/s", v, s, matched, [=](const Scene& sc, const std::vector<Sample>& x) {
            const auto h = bottom_height(sc, x, gap);
            const double pen = -metrics::min_value(h);
            const auto down = metrics::crossings(h, 0.0, metrics::Crossing::down);
            const auto up = metrics::crossings(h, 0.0, metrics::Crossing::up);
            const double tc = down.empty() || up.empty() ? NAN : up[0] - down[0];
            const bool ok = std::abs(pen / bounce.max_penetration - 1.0) <= 0.02 &&
                            std::abs(tc / bounce.contact_time - 1.0) <= 0.02;
            char b[200];
            std::snprintf(b, sizeof b, "peak penetration %.4g vs %.4g m, contact time %.4g vs %.4g s (2 %%: 1-DOF spring oracle)",
                          pen, bounce.max_penetration, tc, bounce.contact_time);
            return Judgement{ok, b};
        });
    }
    // a long run of a resting block released touching (undamped: it swings between 0 and 2 mg/K)
    {
        Scene s = load(rest, {});
        double dt = 1e-4;
        if (dem) {
            auto b = find_backend(backends, "dem").make();
            b->build(s, RunOptions{});
            dt = b->time_step();
        }
        s.run.dt = dt;
        s.run.duration = double(long_steps) * dt;
        s.run.output_interval = s.run.duration / 3999.0;   // 4000 rows; incommensurate with the period
        add("long run", g(double(long_steps)) + " steps", double(long_steps), s, matched,
            [](const Scene& sc, const std::vector<Sample>& x) {
                const double d = 2600.0 * 9.81 / sc.contact.kn;
                auto h = bottom_height(sc, x, 0.0);
                const double hi = -metrics::min_value(h), lo = -metrics::max_value(h);
                double side = 0.0;
                for (const auto& y : x) side = std::max(side, std::hypot(y.blocks[0].position.x(), y.blocks[0].position.y()));
                const bool ok = std::abs(0.5 * (hi + lo) / d - 1.0) <= 0.01 && hi <= 2.02 * d && side < 1e-3;
                char b[200];
                std::snprintf(b, sizeof b, "mid-swing %.4g vs mg/K %.4g m (1 %%), peak %.4g vs 2mg/K, sideways %.2g m (< 1 mm)",
                              0.5 * (hi + lo), d, hi, side);
                return Judgement{ok, b};
            });
    }
    return out;
}

}  // namespace cairn::bench
