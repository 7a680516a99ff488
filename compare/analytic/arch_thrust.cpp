#include "arch_thrust.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cairn::oracle {

namespace {

/// a·(u, v) ≤ b with u = H, v = H·y_c
struct HalfPlane {
    double a0, a1, b;
};

/// the constraints of the half arch from the crown to the springing at thickness t (R = 1)
std::vector<HalfPlane> joint_constraints(int n, double t) {
    const double ri = 1.0 - 0.5 * t, re = 1.0 + 0.5 * t;
    // voussoir i spans angles (from the vertical) [π/2 − (i+1)π/n, π/2 − iπ/n]; the half arch from
    // the crown (angle 0) to the springing (π/2) holds the joints at angles φ_k = π/2 − kπ/n ≥ 0
    // and, for odd n, half of the keystone
    std::vector<HalfPlane> out;
    double weight = 0.0, moment_x = 0.0;   // weight (per unit R·t·ρg) and Σ W·x of the crown part
    // a sector [φa, φb] of the ring: area (φb − φa)·t, centroid radius ρ at mid-angle
    auto add_sector = [&](double fa, double fb) {
        const double d = fb - fa, area = d * t;
        const double rho = (2.0 / 3.0) * (re * re * re - ri * ri * ri) / (re * re - ri * ri) * std::sin(0.5 * d) / (0.5 * d);
        weight += area;
        moment_x += area * rho * std::sin(0.5 * (fa + fb));
    };
    std::vector<double> joints;   // angles from the vertical, ascending from the crown
    for (int k = 0; k <= n; ++k) {
        const double f = 0.5 * M_PI - k * M_PI / n;
        if (f >= -1e-12) joints.push_back(std::max(0.0, f));
    }
    std::sort(joints.begin(), joints.end());
    double prev = 0.0;
    for (double f : joints) {
        if (f > prev) add_sector(prev, f);
        prev = f;
        // the resultant of H at (0, y_c) and the weight W at x̄ crosses the joint line at radius
        // s = (v + W x̄)/(u cos φ + W sin φ): ri ≤ s ≤ re
        const double c = std::cos(f), s = std::sin(f), wx = moment_x, w = weight;
        out.push_back({ri * c, -1.0, wx - ri * w * s});    // ri(u c + W s) ≤ v + W x̄
        out.push_back({-re * c, 1.0, re * w * s - wx});    // v + W x̄ ≤ re(u c + W s)
    }
    out.push_back({-1.0, 0.0, 0.0});   // H ≥ 0: the crown is in compression
    return out;
}

}  // namespace

bool SemicircularArch::thrust_line_fits(double t) const {
    const auto hp = joint_constraints(voussoirs, t);
    // the feasible set is a bounded convex polygon (the springing joint bounds v, a joint near the
    // crown bounds u): it is empty unless one of its vertices, an intersection of two constraint
    // lines, satisfies every constraint
    const double tol = 1e-12;
    for (size_t i = 0; i < hp.size(); ++i)
        for (size_t j = i + 1; j < hp.size(); ++j) {
            const double det = hp[i].a0 * hp[j].a1 - hp[i].a1 * hp[j].a0;
            if (std::abs(det) < 1e-14) continue;
            const double u = (hp[i].b * hp[j].a1 - hp[i].a1 * hp[j].b) / det;
            const double v = (hp[i].a0 * hp[j].b - hp[i].b * hp[j].a0) / det;
            bool ok = true;
            for (const auto& h : hp)
                if (h.a0 * u + h.a1 * v > h.b + tol) {
                    ok = false;
                    break;
                }
            if (ok) return true;
        }
    return false;
}

double SemicircularArch::minimum_thickness() const {
    double lo = 1e-4, hi = 1.0;   // fits at t/R = 1 (the thrust line of a thick ring), not at ~0
    while (hi - lo > 1e-10) {
        const double mid = 0.5 * (lo + hi);
        (thrust_line_fits(mid) ? hi : lo) = mid;
    }
    return hi;
}

}  // namespace cairn::oracle
