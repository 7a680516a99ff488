#include "rigid_body.hpp"

#include <cmath>
#include <cassert>

namespace cairn::dem {

Vec3 RigidBody::omega() const { return omega(q.toRotationMatrix()); }

void RigidBody::set_omega(const Vec3& w) {
    Mat3 r = q.toRotationMatrix();
    L = r * (inertia_body * (r.transpose() * w));
}

double RigidBody::kinetic_energy() const { return 0.5 * mass * v.squaredNorm() + 0.5 * omega().dot(L); }

double kick(RigidBody& b, const Vec3& force, const Vec3& torque, double h, double alpha) {
    // implicit damping: p_new = (p_old + h·F) / (1 + α·h). The kinetic energy changes by
    // (p_new − p_old)·v_avg = h·F·v_avg − α·h·p_new·v_avg: the damping takes α·h·p_new·v_avg
    assert(b.mass > 0.0 && h >= 0.0 && alpha >= 0.0);
    const double damp = 1.0 / (1.0 + alpha * h);
    const Vec3 v_old = b.v, w_old = alpha == 0.0 ? Vec3::Zero() : b.omega();
    b.v = (b.v + h * force / b.mass) * damp;
    b.L = (b.L + h * torque) * damp;
    if (alpha == 0.0) return 0.0;
    Vec3 v_avg = 0.5 * (v_old + b.v), w_avg = 0.5 * (w_old + b.omega());
    return alpha * h * (b.mass * b.v.dot(v_avg) + b.L.dot(w_avg));
}

double half_kick_energy(const RigidBody& b, const Vec3& force, const Vec3& torque, double h) {
    const Mat3 r = b.q.toRotationMatrix();
    const Vec3 dl = h * torque;
    return 0.5 * h * h * force.squaredNorm() / b.mass + 0.5 * dl.dot(r * (b.inv_inertia_body * (r.transpose() * dl)));
}

Vec3 rotation_vector(const Quat& q) {
    Quat u = q.w() < 0 ? Quat(-q.w(), -q.x(), -q.y(), -q.z()) : q;
    Vec3 im = u.vec();
    double s = im.norm();
    if (s < 1e-12) return 2.0 * im;
    return 2.0 * std::atan2(s, u.w()) * im / s;
}

Quat quat_from_rotation_vector(const Vec3& r) {
    const double a2 = r.squaredNorm();
    if (a2 < 1e-4) {
        // |r| < 1e-2 rad (a step's turn): cos(a/2) and sin(a/2)/a by their series to a⁴, whose
        // next terms (a⁶/46080, a⁶/645120) are below 2.2e-17, under the rounding of 1
        const double c = 1.0 - a2 / 8.0 + a2 * a2 / 384.0;
        const double s = 0.5 - a2 / 48.0 + a2 * a2 / 3840.0;
        return Quat(c, s * r.x(), s * r.y(), s * r.z());
    }
    const double a = std::sqrt(a2);
    Vec3 axis = r / a;
    return Quat(Eigen::AngleAxisd(a, axis));
}

void drift(RigidBody& b, double dt) {
    assert(std::abs(b.q.squaredNorm() - 1.0) < 1e-9 && "orientations stay unit quaternions");
    b.x += dt * b.v;
    if (b.L.squaredNorm() == 0.0) return;
    // implicit midpoint for the free rotation: body angular velocity taken at the half-step
    // orientation; a fixed number of fixed-point sweeps keeps it deterministic
    Vec3 w_body = b.inv_inertia_body * (b.q.conjugate() * b.L);
    for (int it = 0; it < 4; ++it) {
        Quat q_mid = (b.q * quat_from_rotation_vector(0.5 * dt * w_body)).normalized();
        const Vec3 w_next = b.inv_inertia_body * (q_mid.conjugate() * b.L);
        if (w_next == w_body) break;   // a fixed point to the last bit: further sweeps repeat it
        w_body = w_next;
    }
    b.q = (b.q * quat_from_rotation_vector(dt * w_body)).normalized();
}

}  // namespace cairn::dem
