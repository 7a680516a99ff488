#include "siconos_relation.hpp"

#include <boost/math/quaternion.hpp>

#include <array>
#include <cmath>

#include <Eigen/Geometry>

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

using Vec3d = Eigen::Vector3d;

Vec3d vec(const SiconosVector& v) { return Vec3d(v(0), v(1), v(2)); }

// two unit tangents completing the unit normal n to a right-handed orthonormal frame
std::array<Vec3d, 2> tangent_basis(const Vec3d& n) {
    const Vec3d helper = std::abs(n.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY();
    const Vec3d t1 = helper.cross(n).normalized();
    return {t1, n.cross(t1)};
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

void PointContactR::computeJachqT(Interaction&, SP::BlockVector q0) {
    const Vec3d n = vec(*_Nc).normalized();
    const std::array<Vec3d, 2> t = tangent_basis(n);
    const Vec3d rows[3] = {n, t[0], t[1]};
    const Vec3d p = vec(*_Pc1);
    // body k's block: +rows (a) or -rows (b) for the translation, then row·(skew(G − P) R) for the
    // angular velocity in the body frame (the velocity of P is v + (R ω)×(P − G))
    for (unsigned k = 0; k < q0->numberOfBlocks(); ++k) {
        const SiconosVector& q = *q0->getAllVect()[k];
        const double sign = k == 0 ? 1.0 : -1.0;
        const Eigen::Matrix3d r = Eigen::Quaterniond(q(3), q(4), q(5), q(6)).normalized().toRotationMatrix();
        const Vec3d arm = vec(q) - p;
        for (int i = 0; i < 3; ++i) {
            const Vec3d angular = r.transpose() * rows[i].cross(arm);
            for (int j = 0; j < 3; ++j) {
                _jachqT->setValue(i, 6 * k + j, sign * rows[i][j]);
                _jachqT->setValue(i, 6 * k + 3 + j, sign * angular[j]);
            }
        }
    }
}

}  // namespace cairn
