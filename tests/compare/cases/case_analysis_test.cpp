// the case analyses on synthetic runs built from the analytic answers: every metric must pass with
// its value at the reference, and a perturbed run must miss
#include <catch2/catch.hpp>

#include <cmath>

#include "analytic/oracles.hpp"
#include "cases/case_analysis.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

namespace {

Scene paper(const std::string& name) {
    return load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/paper/" + name + ".toml");
}

/// samples of block A moving by dz(t) vertically (no rotation), every `dt`
std::vector<Sample> vertical_run(const Scene& s, double duration, double dt, const std::function<double(double)>& dz) {
    std::vector<Sample> out;
    const Vec3 p0 = s.blocks[0].position + s.blocks[0].orientation * s.blocks[0].corners[6];
    for (double t = 0.0; t <= duration + 1e-12; t += dt) {
        Sample x;
        x.t = t;
        x.probes.assign(s.probes.size(), p0 + Vec3(0, 0, dz(t)));
        BlockState b;
        b.position = s.blocks[0].position + Vec3(0, 0, dz(t));
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

TEST_CASE("stability metrics on the exact undamped swing", "[cases]") {
    Scene s = paper("stability");
    oracle::RestingBlock rb{2600.0, 3e7, 9.81};
    const double d = rb.penetration(), w = rb.omega();
    auto run = vertical_run(s, 0.5, 1e-3, [&](double t) { return -d * (1.0 - std::cos(w * t)); });
    auto a = cases::analyse_case(s, run, {true});
    for (const auto& m : a.metrics) {
        INFO(m.name << " = " << m.value << " vs " << m.reference);
        CHECK(m.pass());
        // 1 ms samples of a 58 ms period: crossings and mid-swing within 1e-3 of the truth
        CHECK(m.relative_error() == Approx(0.0).margin(1e-3));
    }
    CHECK(find(a, "period").value == Approx(rb.period()).epsilon(1e-4));
    // a block 2 % too stiff misses the penetration by 2 %
    auto stiff = vertical_run(s, 0.5, 1e-3, [&](double t) { return -d / 1.02 * (1.0 - std::cos(w * t)); });
    CHECK_FALSE(find(cases::analyse_case(s, stiff, {true}), "equilibrium penetration").pass());
}

TEST_CASE("impact metrics on the 1-DOF oracle's own path", "[cases]") {
    for (const char* name : {"impact", "impact_damped"}) {
        INFO(name);
        Scene s = paper(name);
        const double c = s.contact.damping_rule == ContactDampingRule::ratio
                             ? oracle::dashpot_for_ratio(s.contact.damping, 3e7, 2600.0) : 0.0;
        oracle::DampedDrop o{2600.0, 3e7, c, 9.81, 0.1};
        std::vector<double> t;
        for (int i = 0; i <= 700; ++i) t.push_back(i * 1e-3);
        auto h = o.heights(t);
        auto run = vertical_run(s, 0.7, 1e-3, [&](double x) { return h[size_t(std::lround(x * 1e3))] - 0.1; });
        auto a = cases::analyse_case(s, run, {true});
        REQUIRE(a.metrics.size() == 4);
        for (const auto& m : a.metrics) {
            INFO(m.name << " = " << m.value << " vs " << m.reference);
            CHECK(m.pass());
        }
        CHECK(a.event_time == Approx(std::sqrt(0.2 / 9.81)).epsilon(1e-3));
    }
}

TEST_CASE("rocking metrics on Housner's angle history, and a rigid run judged as penalty misses", "[cases]") {
    Scene s = paper("rocking");
    oracle::HousnerBlock hb{0.35, 0.5, 9.81};
    const double th0 = s.reference->values.at("theta0");
    std::vector<double> t;
    for (int i = 0; i <= 3000; ++i) t.push_back(i * 1e-3);
    auto th = hb.angles(th0, hb.velocity_ratio(), t);
    std::vector<Sample> run;
    for (size_t i = 0; i < t.size(); ++i) {
        Sample x;
        x.t = t[i];
        x.probes.assign(s.probes.size(), Vec3::Zero());
        BlockState b;
        b.orientation = Quat(Eigen::AngleAxisd(th[i], Vec3::UnitY()));
        x.blocks.push_back(b);
        run.push_back(x);
    }
    auto rigid = cases::analyse_case(s, run, {false});
    for (const auto& m : rigid.metrics) {
        INFO(m.name << " = " << m.value << " vs " << m.reference);
        CHECK(m.pass());
    }
    CHECK(find(rigid, "first impact").value == Approx(0.76160).epsilon(2e-3));
    CHECK(find(rigid, "impact velocity ratio").value == Approx(0.50671).epsilon(0.01));
    // the same path judged as an undamped penalty run (no loss expected) misses the amplitude
    auto penalty = cases::analyse_case(s, run, {true});
    CHECK_FALSE(find(penalty, "amplitude after 1st impact").pass());
    CHECK(find(penalty, "first impact").pass());
}
