// case (d): a cube tumbling down a slope face after face; coarse oracles only (physics.md)
#include <algorithm>
#include <cmath>

#include "cases/case_util.hpp"
#include "cases/kinds.hpp"

namespace cairn::cases {

CaseAnalysis analyse_rolling(const Scene& scene, const std::vector<Sample>& s, ContactKind) {
    using namespace metrics;
    const int a = scene.reference->block, f = free_index(scene, a);
    const double slope = scene.reference->values.at("slope"), g = gravity(scene), m = block_mass(scene, a);
    // the cube's edge: its extent along block-frame x
    double lo = 1e300, hi = -1e300;
    for (const auto& c : scene.blocks[a].corners) { lo = std::min(lo, c.x()); hi = std::max(hi, c.x()); }
    const double edge = hi - lo, drop_ref = edge * std::sin(slope);
    // the run is judged while the centre of mass is above the slope block (the first fixed block,
    // descending toward +x)
    double x_end = 1e300;
    for (const auto& b : scene.blocks)
        if (b.fixed) {
            x_end = -1e300;
            for (const auto& c : b.corners) x_end = std::max(x_end, (b.position + b.orientation * c).x());
            break;
        }
    Series x = com_series(s, f, 0, false), z = com_series(s, f, 2, false);
    Series turn = angle_series(s, f, Vec3::UnitY());
    size_t n_on = 0;
    while (n_on < s.size() && x.y[n_on] <= x_end) ++n_on;
    CaseAnalysis r;
    r.quantity = "drop of A's centre of mass, m";
    r.measured.t = z.t;
    for (double y : z.y) r.measured.y.push_back(z.y[0] - y);
    const double t_on = n_on ? s[n_on - 1].t : 0.0;

    // quarter turns completed on the slope
    int faces = 0;
    double t_face = 0.0;
    for (size_t i = 0; i < n_on; ++i) {
        int k = int(std::floor(std::abs(turn.y[i] - turn.y[0]) / (0.5 * M_PI) + 1e-9));
        if (k > faces) { faces = k; t_face = s[i].t; if (k == 1) { r.event_time = s[i].t; r.has_event = true; } }
    }
    r.metrics.push_back(at_least("faces crossed on the slope", "", faces, 1.0,
                                 "A must tip and roll at least once (judged until it leaves the slope at t = " +
                                     std::to_string(t_on) + " s)"));
    const std::string coarse = "coarse oracle (physics.md d): 10 %, the cube hops and the edge sinks at soft kn";
    if (faces > 0) {
        const double zk = interpolate(z, t_face), xk = interpolate(x, t_face);
        const double along = ((xk - x.y[0]) * std::cos(slope) - (zk - z.y[0]) * std::sin(slope)) / faces;
        r.metrics.push_back(relative("drop per face", "m", (z.y[0] - zk) / faces, drop_ref, 0.10,
                                     "edge·sin(slope); " + coarse));
        r.metrics.push_back(relative("advance along the slope per face", "m", along, edge, 0.10,
                                     "one edge per face (no slip at μ > tan slope); " + coarse));
    } else {
        r.metrics.push_back(missing("drop per face", "m", drop_ref, 0.10, Check::relative, "no face crossed"));
    }
    // monotonic descent: how far the centre of mass climbs above its lowest point so far
    double lowest = z.y[0], rise = 0.0, excess = -1e300;
    const double ke0 = s[0].energy.kinetic;
    for (size_t i = 0; i < n_on; ++i) {
        lowest = std::min(lowest, z.y[i]);
        rise = std::max(rise, z.y[i] - lowest);
        excess = std::max(excess, s[i].energy.kinetic - ke0 - m * g * (z.y[0] - z.y[i]));
    }
    r.metrics.push_back(at_most("largest climb of the centre of mass", "m", rise, 0.0, 0.04 * drop_ref,
                                "monotonic descent; 4 % of the drop per face for hops"));
    r.metrics.push_back(at_most("kinetic energy above the bound", "J", excess, 0.0, 0.01 * m * g * drop_ref,
                                "KE ≤ KE0 + m g (height lost); 1 % of one face's m g drop"));
    return r;
}

}  // namespace cairn::cases
