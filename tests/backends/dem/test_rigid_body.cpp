// A rigid body's leapfrog against closed forms: the kick's momenta and damping work, spin about a
// principal axis, the torque-free precession of a symmetric top, and the conserved energy and
// angular momentum of an asymmetric body's free rotation.
#include <catch2/catch.hpp>

#include <cmath>

#include "dem/rigid_body.hpp"

using namespace cairn;
using dem::RigidBody;

namespace {

// a body of mass 3 kg with principal moments (i1, i2, i3) along the body axes
RigidBody body(double i1, double i2, double i3) {
    RigidBody b;
    b.mass = 3.0;
    b.inertia_body = Vec3(i1, i2, i3).asDiagonal();
    b.inv_inertia_body = Vec3(1 / i1, 1 / i2, 1 / i3).asDiagonal();
    return b;
}

// body-frame angular velocity, rad/s
Vec3 body_omega(const RigidBody& b) { return b.q.conjugate() * b.omega(); }

}  // namespace

TEST_CASE("dem rigid body: angular velocity, momentum and kinetic energy agree", "[dem][rigid_body]") {
    RigidBody b = body(1.0, 2.0, 4.0);
    b.q = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    b.v = Vec3(1, -2, 0.5);
    const Vec3 w(0.3, -1.1, 2.0);
    b.set_omega(w);
    CHECK((b.omega() - w).norm() < 1e-14);   // a round trip through R·I·Rᵀ: round-off only
    // ½·m·v² + ½·ωᵀ·I·ω with ω in body axes
    const Vec3 wb = b.q.conjugate() * w;
    const double ke = 0.5 * 3.0 * b.v.squaredNorm() + 0.5 * (wb[0] * wb[0] * 1 + wb[1] * wb[1] * 2 + wb[2] * wb[2] * 4);
    CHECK(b.kinetic_energy() == Approx(ke).epsilon(1e-14));
    CHECK((b.point_velocity(b.x + Vec3(1, 0, 0)) - (b.v + w.cross(Vec3(1, 0, 0)))).norm() < 1e-13);
}

TEST_CASE("dem rigid body: a kick adds the impulse, damping takes the booked energy", "[dem][rigid_body]") {
    RigidBody b = body(1.0, 2.0, 4.0);
    b.v = Vec3(1, 0, 0);
    b.L = Vec3(0, 0.5, 0);
    const Vec3 f(6, 3, 0), tq(0, 0, 2);
    const double h = 0.01;
    CHECK(dem::kick(b, f, tq, h, 0.0) == 0.0);
    CHECK((b.v - Vec3(1.02, 0.01, 0)).norm() < 1e-15);   // v + h·F/m
    CHECK((b.L - Vec3(0, 0.5, 0.02)).norm() < 1e-15);    // L + h·τ

    // implicit damping α: momenta (p + h·F)/(1 + α·h), and the kinetic energy's change is the
    // force's work on the mean velocity less the booked dissipation, exactly (ΔKE = Δp·v_mean)
    const double alpha = 5.0;
    const RigidBody before = b;
    const double dissipated = dem::kick(b, f, Vec3::Zero(), h, alpha);
    CHECK((b.v - (before.v + h * f / 3.0) / (1 + alpha * h)).norm() < 1e-15);
    CHECK(dissipated > 0.0);
    const Vec3 v_mean = 0.5 * (before.v + b.v);
    const double work = h * f.dot(v_mean);
    CHECK(b.kinetic_energy() - before.kinetic_energy() == Approx(work - dissipated).epsilon(1e-12));
}

TEST_CASE("dem rigid body: rotation vectors and quaternions are inverse", "[dem][rigid_body]") {
    for (const Vec3& r : {Vec3(0.1, -0.2, 0.3), Vec3(1e-14, 0, 0), Vec3(0, 3.0, 0), Vec3(-1, 1, 2)}) {
        const Quat q = dem::quat_from_rotation_vector(r);
        CHECK(std::abs(q.norm() - 1.0) < 1e-15);
        CHECK((dem::rotation_vector(q) - r).norm() < 1e-12 * std::max(1.0, r.norm()));
        // the rotation by |r| about r/|r|
        if (r.norm() > 1e-6) CHECK(q.angularDistance(Quat(Eigen::AngleAxisd(r.norm(), r.normalized()))) < 1e-12);
    }
    // a step's turn (under 1e-2 rad) by its series: the same quaternion to the rounding of 1 (its
    // truncation is below 2.2e-17; a few roundings of the sums and products give ~1e-16)
    for (const Vec3& r : {Vec3(0.0, 9.99e-3, 0.0), Vec3(4e-3, -5e-3, 5e-3), Vec3(1e-3, 2e-4, -3e-4), Vec3(0, 0, 1e-7)}) {
        const Quat q = dem::quat_from_rotation_vector(r);
        const Quat exact(Eigen::AngleAxisd(r.norm(), r.normalized()));
        CHECK((q.coeffs() - exact.coeffs()).norm() < 3e-16);
        CHECK(std::abs(q.norm() - 1.0) < 3e-16);
    }
    // −q is the same rotation: the short way round
    const Quat q = dem::quat_from_rotation_vector(Vec3(0, 0, 0.4));
    const Quat neg(-q.w(), -q.x(), -q.y(), -q.z());
    CHECK((dem::rotation_vector(neg) - Vec3(0, 0, 0.4)).norm() < 1e-14);
}

TEST_CASE("dem rigid body: torque-free spin about a principal axis stays on it", "[dem][rigid_body]") {
    // the body angular velocity is constant, so the midpoint rule is exact: after n steps the
    // orientation is the rotation by ω·t about the axis, to round-off growing with the steps
    RigidBody b = body(1.0, 2.0, 4.0);
    const double w = 3.0, dt = 1e-3;
    const int n = 2000;
    for (int axis = 0; axis < 3; ++axis) {
        b.q = Quat::Identity();
        b.set_omega(w * Vec3::Unit(axis));
        const Vec3 L0 = b.L;
        for (int i = 0; i < n; ++i) dem::drift(b, dt);
        CHECK((b.L - L0).norm() == 0.0);   // the drift never touches L
        CHECK((b.omega() - w * Vec3::Unit(axis)).norm() < 1e-10 * w);
        CHECK(b.q.angularDistance(Quat(Eigen::AngleAxisd(w * n * dt, Vec3::Unit(axis)))) < 1e-10);
    }
}

TEST_CASE("dem rigid body: a symmetric top precesses at (I3 - I1)/I1 times its spin", "[dem][rigid_body]") {
    // I1 = I2: ω3 stays and (ω1, ω2) turns about the body symmetry axis at Ω = (I3 − I1)/I1·ω3
    // (Euler's equations); the scheme is second order, so the phase error falls 4× as dt halves
    const double i1 = 1.0, i3 = 2.5, w3 = 4.0, wp = 0.5, t_end = 2.0;
    const double big_omega = (i3 - i1) / i1 * w3;
    auto error_at = [&](double dt) {
        RigidBody b = body(i1, i1, i3);
        b.set_omega(Vec3(wp, 0, w3));
        const int n = int(std::lround(t_end / dt));
        for (int i = 0; i < n; ++i) dem::drift(b, dt);
        const Vec3 wb = body_omega(b);
        // I1·dω2/dt = (I3 − I1)·ω3·ω1: ω1 + i·ω2 = wp·e^{iΩt} in the body frame
        const Vec3 exact(wp * std::cos(big_omega * t_end), wp * std::sin(big_omega * t_end), w3);
        return (wb - exact).norm();
    };
    const double e1 = error_at(2e-3), e2 = error_at(1e-3);
    // a second-order rotation lags by at most (|ω|·dt)² per radian turned: Ω·t·(|ω|·dt)² ≈ 8e-4 rad
    const double lag = big_omega * t_end * (w3 * w3 + wp * wp) * 2e-3 * 2e-3;
    CHECK(e1 < wp * lag);
    CHECK(e1 / e2 == Approx(4.0).epsilon(0.05));   // second order, up to higher terms
}

TEST_CASE("dem rigid body: free rotation of an asymmetric body keeps energy and angular momentum", "[dem][rigid_body]") {
    // close to the intermediate axis the motion tumbles; the world angular momentum is never
    // touched by the drift, and the kinetic energy ½·L·ω is held by the midpoint rotation to
    // second order in ω·dt with no secular growth
    RigidBody b = body(1.0, 2.0, 4.0);
    b.set_omega(Vec3(0.05, 2.0, 0.05));
    const Vec3 L0 = b.L;
    const double e0 = b.kinetic_energy(), dt = 1e-3;
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
        dem::drift(b, dt);
        worst = std::max(worst, std::abs(b.kinetic_energy() - e0) / e0);
    }
    CHECK((b.L - L0).norm() == 0.0);
    CHECK(worst < 4e-6);   // (|ω|·dt)² = 4e-6 bounds the midpoint rule's oscillation of the energy
    // the orientation stays a unit quaternion (renormalised every step)
    CHECK(std::abs(b.q.norm() - 1.0) < 1e-14);
}

TEST_CASE("dem rigid body: the drift's sweeps stop at their fixed point with the bits of all four", "[dem][rigid_body]") {
    // pins the early exit: the rotation's fixed-point sweeps stop once one repeats the last to the
    // bit, so the step must equal the plain four sweeps, slow (a brick at rest) or fast: exactly in
    // a portable build; a native build may fuse multiply-adds (FMA) differently in the test's copy,
    // a last-bit difference of a unit quaternion (2 ulp of 1 allowed, 200 steps)
    auto four_sweeps = [](RigidBody b, double dt) {
        b.x += dt * b.v;
        Vec3 w_body = b.inv_inertia_body * (b.q.conjugate() * b.L);
        for (int it = 0; it < 4; ++it) {
            const Quat q_mid = (b.q * dem::quat_from_rotation_vector(0.5 * dt * w_body)).normalized();
            w_body = b.inv_inertia_body * (q_mid.conjugate() * b.L);
        }
        b.q = (b.q * dem::quat_from_rotation_vector(dt * w_body)).normalized();
        return b;
    };
    for (double spin : {1e-9, 1e-4, 0.3, 5.0, 40.0}) {
        RigidBody b = body(1.0, 2.0, 4.0);
        b.q = Quat(Eigen::AngleAxisd(0.4, Vec3(1, -2, 1).normalized()));
        b.set_omega(spin * Vec3(0.6, -1.0, 0.3));
        for (int i = 0; i < 200; ++i) {
            const RigidBody expected = four_sweeps(b, 1e-3);
            dem::drift(b, 1e-3);
            REQUIRE((b.q.coeffs() - expected.q.coeffs()).norm() <= 4.5e-16);
            b = expected;   // the next step from the same state: no drift of round-off
        }
    }
}
