// The world's refresh of the contact candidates: no contact is missed between refreshes, however
// fast the blocks move for the broad-phase margin.
#include <catch2/catch.hpp>

#include <cmath>

#include "dem_test_util.hpp"
#include "support/scene_builder.hpp"

using namespace cairn;

namespace {

constexpr double kEdge = 0.1;      // m
constexpr double kMargin = 2e-3;   // m: run.contact_margin
constexpr double kDt = 1e-5;       // s

// two free 0.1 m cubes along x, faces `gap` (m) apart, closing at `move` (m) a step each; no
// gravity; kn 1e12 N/m³ keeps their impact shallow (under 0.01 m at 400 m/s each; ω·dt ≈ 0.6)
Scene closing_pair(double gap, double move) {
    Scene s = test::stone_scene();
    s.gravity = Vec3::Zero();
    s.contact.scheme = ContactScheme::overlap;
    s.contact.kn = 1e12;
    s.contact.ks = 1e11;
    s.run.dt = kDt;
    s.run.contact_margin = kMargin;
    s.run.contact_interval = 1000;   // only the margin check refreshes
    const double x = 0.5 * (kEdge + gap);
    test::add_box(s, "A", Vec3(kEdge, kEdge, kEdge), Vec3(-x, 0, 0), false);
    test::add_box(s, "B", Vec3(kEdge, kEdge, kEdge), Vec3(x, 0, 0), false);
    s.blocks[0].velocity = Vec3(move / kDt, 0, 0);
    s.blocks[1].velocity = Vec3(-move / kDt, 0, 0);
    return s;
}

// the first sample at which the cubes overlap and whether it had contacts, then whether they came
// apart again (the impact reversed both)
struct Impact {
    bool touched_with_contact = false;
    bool bounced = false;
};

Impact run_pair(double gap, double move) {
    auto b = test::build_dem(closing_pair(gap, move));
    Impact r;
    bool touched = false;
    for (int i = 0; i < 400; ++i) {
        REQUIRE(b->step() == StepStatus::ok);
        const Sample s = b->sample();
        const double apart = s.blocks[1].position.x() - s.blocks[0].position.x() - kEdge;
        if (!touched && apart < 0.0) {
            touched = true;
            r.touched_with_contact = s.contacts > 0;
        }
        if (s.blocks[0].velocity.x() < 0.0 && s.blocks[1].velocity.x() > 0.0) r.bounced = true;
    }
    return r;
}

}  // namespace

TEST_CASE("a pair closing within half the margin a step is caught at its first overlap", "[dem][contact]") {
    // each cube moves 0.3 of the margin a step, so the two close by 0.6 of it: a check that left
    // out the step about to be taken let each move half the margin plus a step (1.6 margins of
    // closing) on the candidates of a refresh that had found them more than a margin apart
    for (double gap : {1.05 * kMargin, 1.2 * kMargin, 1.5 * kMargin, 3.1 * kMargin}) {
        INFO("gap " << gap << " m");
        const Impact r = run_pair(gap, 0.3 * kMargin);
        CHECK(r.touched_with_contact);
        CHECK(r.bounced);
    }
}

TEST_CASE("a pair closing by more than the margin a step is still caught: the margin grows", "[dem][contact]") {
    // each cube moves 0.6 and 2 margins a step (120 and 400 m/s): a refresh with the scene's margin
    // would leave the pair out and let the cubes pass into each other before the next one
    for (double move : {0.6 * kMargin, 2.0 * kMargin})
        for (double gap : {1.05 * kMargin, 1.9 * kMargin, 5.3 * kMargin}) {
            INFO("move " << move << " m a step, gap " << gap << " m");
            const Impact r = run_pair(gap, move);
            CHECK(r.touched_with_contact);
            CHECK(r.bounced);
        }
}
