#include "geometry/spring_bed.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace cairn {

double spring_bed_omega2(const std::vector<BedSpring>& springs, const Vec3& n, double kn, double ks, const Vec3& c,
                         double m, const Mat3& inertia) {
    using Mat6 = Eigen::Matrix<double, 6, 6>;
    using Vec6 = Eigen::Matrix<double, 6, 1>;
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    Mat6 k = Mat6::Zero();
    for (const auto& [p, area] : springs) {
        const Vec3 r = p - c;
        auto add = [&](const Vec3& d, double stiff) {
            Vec6 g;
            g << d, r.cross(d);
            k += stiff * area * g * g.transpose();
        };
        add(n, kn);
        add(t1, ks);
        add(t2, ks);
    }
    // M^(−1/2) K M^(−1/2) with M = diag(m, I)
    Eigen::SelfAdjointEigenSolver<Mat3> ei(inertia);
    const Mat3 inertia_inv_sqrt =
        ei.eigenvectors() * ei.eigenvalues().cwiseSqrt().cwiseInverse().asDiagonal() * ei.eigenvectors().transpose();
    Mat6 s = Mat6::Zero();
    s.topLeftCorner<3, 3>() = Mat3::Identity() / std::sqrt(m);
    s.bottomRightCorner<3, 3>() = inertia_inv_sqrt;
    const Mat6 a = s * k * s;
    Eigen::SelfAdjointEigenSolver<Mat6> es(a, Eigen::EigenvaluesOnly);
    return es.eigenvalues().maxCoeff();
}

}  // namespace cairn
