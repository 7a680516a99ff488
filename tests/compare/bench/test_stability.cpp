// the stability classifier on synthetic run results, the penetration measure, the CSV round trip
#include <catch2/catch.hpp>

#include "bench/stability.hpp"
#include "geometry/hexahedron.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;
using namespace cairn::bench;

TEST_CASE("bench stability: classes of synthetic runs", "[bench]") {
    StabilityInput ok{"completed", true, false, 1e-6, true, true};
    CHECK(classify(ok) == StabilityClass::stable);

    auto blew = ok;
    blew.outcome = "unstable";
    blew.oracle_pass = false;   // a blow-up is unstable whatever its partial trajectory says
    CHECK(classify(blew) == StabilityClass::unstable);
    blew.outcome = "failed";
    CHECK(classify(blew) == StabilityClass::unstable);

    auto refused = ok;
    refused.outcome = "refused";
    CHECK(classify(refused) == StabilityClass::refused);

    auto drift = ok;
    drift.energy_drift = true;   // the runner's flag
    CHECK(classify(drift) == StabilityClass::drifting);
    drift.energy_drift = false;
    drift.max_balance_error = 1.5 * kDriftBound;   // beyond the stated bound without the flag
    CHECK(classify(drift) == StabilityClass::drifting);
    drift.max_balance_error = 0.5 * kDriftBound;
    CHECK(classify(drift) == StabilityClass::stable);

    // an engine that does not book its dissipation is never called drifting for it
    auto rigid = ok;
    rigid.energy_booked = false;
    rigid.energy_drift = true;
    rigid.max_balance_error = 0.5;
    CHECK(classify(rigid) == StabilityClass::stable);
    rigid.oracle_pass = false;
    CHECK(classify(rigid) == StabilityClass::wrong);

    auto wrong = ok;
    wrong.oracle_pass = false;
    CHECK(classify(wrong) == StabilityClass::wrong);
    wrong.energy_drift = true;   // drifting wins over wrong: the energy problem is the cause to report
    CHECK(classify(wrong) == StabilityClass::drifting);
}

TEST_CASE("bench stability: penetration of the reference block's lowest corner into the fixed block", "[bench]") {
    Scene s;
    s.materials.push_back(test::stone());
    BlockDef a, b;
    a.name = "A";
    a.size = Vec3(1, 1, 1);
    a.corners = box_corners(a.size);
    a.position = Vec3(0, 0, 0.5);
    b = a;
    b.name = "B";
    b.fixed = true;
    b.position = Vec3(0, 0, -0.5);
    s.blocks = {a, b};
    s.reference = ReferenceDef{"rest", 0, {}};
    Sample x0, x1;
    x0.blocks.push_back({Vec3(0, 0, 0.5)});
    x1.blocks.push_back({Vec3(0, 0, 0.5 - 2e-3)});
    CHECK(max_penetration(s, {x0}) == Approx(0.0).margin(1e-15));
    CHECK(max_penetration(s, {x0, x1}) == Approx(2e-3));   // the block sank 2 mm into B's top at z = 0
    // tilted 0.1 rad about y about its centre: a bottom corner goes down by 0.5 (cos + sin − 1)... exactly
    Sample x2;
    x2.blocks.push_back({Vec3(0, 0, 0.5), Quat(Eigen::AngleAxisd(0.1, Vec3::UnitY()))});
    CHECK(max_penetration(s, {x2}) == Approx(0.5 * (std::cos(0.1) + std::sin(0.1)) - 0.5));
}

TEST_CASE("bench stability: stability.csv round-trips every field that the map reads", "[bench]") {
    StabilityPoint p;
    p.backend = "ode";
    p.parameter = "impact speed";
    p.value_text = "20 m/s";
    p.value = 20.0;
    p.cls = StabilityClass::wrong;
    p.max_balance_error = 0.004;
    p.energy_booked = true;
    p.penetration = 0.19;
    p.check = "MISS peak penetration 0.2 vs 0.19, contact time";
    const auto back = parse_stability_csv(stability_csv({p}));
    REQUIRE(back.size() == 1);
    CHECK(back[0].backend == "ode");
    CHECK(back[0].parameter == "impact speed");
    CHECK(back[0].value_text == "20 m/s");
    CHECK(back[0].cls == StabilityClass::wrong);
    CHECK(back[0].penetration == Approx(0.19));
    CHECK(back[0].check == p.check);
}
