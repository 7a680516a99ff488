#include "siconos_relation.hpp"

#include <boost/math/quaternion.hpp>

namespace cairn {

namespace {

// world position of a body-frame vector v: rotated by the body's quaternion q(3..6), plus q(0..2)
// when `translate`
void to_world(const SiconosVector& q, const SiconosVector& v, SiconosVector& out, bool translate) {
    ::boost::math::quaternion<double> r(q(3), q(4), q(5), q(6));
    ::boost::math::quaternion<double> p(0, v(0), v(1), v(2));
    p = r * p * conj(r);
    out(0) = p.R_component_2() + (translate ? q(0) : 0.0);
    out(1) = p.R_component_3() + (translate ? q(1) : 0.0);
    out(2) = p.R_component_4() + (translate ? q(2) : 0.0);
}

}  // namespace

PointContactR::PointContactR(const double on_a[3], const double on_b[3], const double normal[3]) {
    set(on_a, on_b, normal);
}

void PointContactR::set(const double on_a[3], const double on_b[3], const double normal[3]) {
    for (int k = 0; k < 3; ++k) {
        (*_relPc1)(k) = on_a[k];
        (*_relPc2)(k) = on_b[k];
        (*_relNc)(k) = normal[k];
    }
}

void PointContactR::computeh(double, const BlockVector& q0, SiconosVector& y) {
    to_world(*q0.getAllVect()[0], *_relPc1, *_Pc1, true);
    if (q0.numberOfBlocks() > 1) {
        to_world(*q0.getAllVect()[1], *_relPc2, *_Pc2, true);
        to_world(*q0.getAllVect()[1], *_relNc, *_Nc, false);
    } else {
        *_Pc2 = *_relPc2;
        *_Nc = *_relNc;
    }
    double gap = 0.0;
    for (int k = 0; k < 3; ++k) gap += (*_Nc)(k) * ((*_Pc1)(k) - (*_Pc2)(k));
    y.zero();
    y(0) = gap;   // the tangential rows are velocity-level only
}

}  // namespace cairn
