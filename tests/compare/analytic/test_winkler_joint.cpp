// the rectangular Winkler joint's resultant under a lean in any direction (BlockStack at an angle)
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "analytic/winkler_joint.hpp"

using namespace cairn::oracle;

TEST_CASE("a Winkler joint's resultant under a lean in any direction, against a fine grid", "[oracle][pushover]") {
    // a 0.4 × 0.3 m joint, kn 1e9, carrying 5 kN; the midpoint rule on 1000 × 750 cells, with w
    // found by bisection to 1e-14 m, has a relative error of order 1e-6 (the cut cells along the
    // line where the joint opens)
    const double a = 0.2, c = 0.15, kn = 1e9, n = 5000.0;
    auto grid = [&](const Eigen::Vector2d& lean) {
        const int nx = 1000, ny = 750;
        const double hx = 2 * a / nx, hy = 2 * c / ny;
        auto sums = [&](double w, Eigen::Vector2d* moment) {
            double f = 0.0;
            Eigen::Vector2d m = Eigen::Vector2d::Zero();
            for (int i = 0; i < nx; ++i)
                for (int j = 0; j < ny; ++j) {
                    const Eigen::Vector2d r(-a + (i + 0.5) * hx, -c + (j + 0.5) * hy);
                    const double d = std::max(0.0, w + lean.dot(r));
                    f += kn * d * hx * hy;
                    m += kn * d * hx * hy * r;
                }
            if (moment) *moment = m;
            return f;
        };
        double lo = -1.0, hi = 1.0;
        while (hi - lo > 1e-14) {
            const double mid = 0.5 * (lo + hi);
            (sums(mid, nullptr) > n ? hi : lo) = mid;
        }
        Eigen::Vector2d m;
        sums(0.5 * (lo + hi), &m);
        return m;
    };
    // closed all over: kn·I·lean exactly (I = 4ac·diag(a², c²)/3)
    const Eigen::Vector2d small(1e-6, -2e-6);
    const Eigen::Vector2d closed = winkler_joint_moment(small, n, a, c, kn);
    CHECK(closed.x() == Approx(kn * 4 * a * c * a * a / 3 * small.x()).epsilon(1e-12));
    CHECK(closed.y() == Approx(kn * 4 * a * c * c * c / 3 * small.y()).epsilon(1e-12));
    // open along a side, and open past a corner (a triangle or pentagon left closed)
    for (const Eigen::Vector2d& lean : {Eigen::Vector2d(4e-4, 0.0), Eigen::Vector2d(3e-4, 2e-4), Eigen::Vector2d(-1e-3, 6e-4)}) {
        const Eigen::Vector2d exact = winkler_joint_moment(lean, n, a, c, kn), fine = grid(lean);
        INFO("lean " << lean.transpose() << ": " << exact.transpose() << " against " << fine.transpose());
        CHECK((exact - fine).norm() < 1e-5 * exact.norm());
        CHECK(exact.norm() < n * std::hypot(a, c));   // the resultant stays inside the joint
    }
}
