#pragma once
// the Signorini relation of one point contact between two Newton–Euler bodies (or one body and a
// fixed block): the gap y = n·(p_a − p_b), with p_a fixed on body a, p_b and n fixed on body b
// (in the world when b is fixed); Siconos's NewtonEuler3DR gives its Jacobian from the points

#include <SiconosKernel.hpp>

namespace cairn {

class PointContactR : public NewtonEuler3DR {
public:
    /// points and normal in the body frames (b's in the world when b is fixed), m
    PointContactR(const double on_a[3], const double on_b[3], const double normal[3]);
    /// move the contact to new points and normal, same frames as the constructor
    void set(const double on_a[3], const double on_b[3], const double normal[3]);
    void computeh(double time, const BlockVector& q0, SiconosVector& y) override;
};

}  // namespace cairn
