#pragma once
// the Signorini relation of one point contact between two Newton–Euler bodies (or one body and a
// fixed block): the gap y = n·(p_a − p_b), with p_a fixed on body a, p_b and n fixed on body b
// (in the world when b is fixed); its Jacobian from the points and an orthonormal contact frame

#include <SiconosKernel.hpp>

namespace cairn {

class PointContactR : public NewtonEuler3DR {
public:
    /// points and normal in the body frames (b's in the world when b is fixed), m
    PointContactR(const double on_a[3], const double on_b[3], const double normal[3]);
    /// move the contact to new points and normal, same frames as the constructor
    void set(const double on_a[3], const double on_b[3], const double normal[3]);
    void computeh(double time, const BlockVector& q0, SiconosVector& y) override;
    /// the Jacobian of the contact-frame velocities (n, t1, t2) over the bodies' twists. Replaces
    /// NewtonEuler3DR's, whose tangents (numerics' orthoBaseFromVector in 4.4) are neither
    /// orthogonal to n nor unit when |n_z| is the largest component and n_x ≠ n_y: on a 45° slope
    /// t1 had 0.5 along n and t2 was 0.87 long, so friction came out at about 0.7 of mu
    void computeJachqT(Interaction& inter, SP::BlockVector q0) override;
};

}  // namespace cairn
