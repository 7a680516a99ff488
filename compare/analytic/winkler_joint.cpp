#include "winkler_joint.hpp"

#include <cmath>
#include <vector>

namespace cairn::oracle {

namespace {

using Point = Eigen::Vector2d;

/// the rectangle's part where w + lean·r ≥ 0, a convex polygon (counter-clockwise)
std::vector<Point> closed_part(const Point& lean, double w, double a, double c) {
    const std::vector<Point> rect = {{-a, -c}, {a, -c}, {a, c}, {-a, c}};
    std::vector<Point> out;
    for (size_t i = 0; i < rect.size(); ++i) {
        const Point& p = rect[i];
        const Point& q = rect[(i + 1) % rect.size()];
        const double dp = w + lean.dot(p), dq = w + lean.dot(q);
        if (dp >= 0) out.push_back(p);
        if ((dp > 0 && dq < 0) || (dp < 0 && dq > 0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
    return out;
}

/// area, first moments and second moments (∫x², ∫y², ∫xy) of a polygon (shoelace formulas)
struct PolygonIntegrals {
    double area = 0.0;
    Point first = Point::Zero();
    Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
};

PolygonIntegrals integrals(const std::vector<Point>& poly) {
    PolygonIntegrals r;
    for (size_t i = 0; i < poly.size(); ++i) {
        const Point& p = poly[i];
        const Point& q = poly[(i + 1) % poly.size()];
        const double cross = p.x() * q.y() - q.x() * p.y();
        r.area += cross / 2.0;
        r.first += (p + q) * cross / 6.0;
        r.second(0, 0) += (p.x() * p.x() + p.x() * q.x() + q.x() * q.x()) * cross / 12.0;
        r.second(1, 1) += (p.y() * p.y() + p.y() * q.y() + q.y() * q.y()) * cross / 12.0;
        r.second(0, 1) += (p.x() * q.y() + 2.0 * p.x() * p.y() + 2.0 * q.x() * q.y() + q.x() * p.y()) * cross / 24.0;
    }
    r.second(1, 0) = r.second(0, 1);
    return r;
}

}  // namespace

Eigen::Vector2d winkler_joint_moment(const Eigen::Vector2d& lean, double n, double a, double c, double kn) {
    // ∫ kn·d⁺ dA grows with w and is convex in it: Newton from a w that closes the whole joint
    // (so the force is at least n there) comes down monotonically to the root
    double w = n / (kn * 4.0 * a * c) + std::abs(lean.x()) * a + std::abs(lean.y()) * c;
    PolygonIntegrals p = integrals(closed_part(lean, w, a, c));
    for (int it = 0; it < 200; ++it) {
        const double force = kn * (w * p.area + lean.dot(p.first));
        if (force - n <= 1e-15 * n || p.area <= 0.0) break;
        w -= (force - n) / (kn * p.area);
        p = integrals(closed_part(lean, w, a, c));
    }
    return kn * (w * p.first + p.second * lean);
}

}  // namespace cairn::oracle
