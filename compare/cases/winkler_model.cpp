#include "cases/winkler_model.hpp"

#include <algorithm>
#include <cmath>

#include "cases/case_util.hpp"
#include "metrics/signal.hpp"

namespace cairn::cases {

oracle::WinklerRocking winkler_model(const Scene& scene, ContactKind contact, const Vec3& axis) {
    const int a = scene.reference->block;
    const auto hb = housner_block(scene, axis);
    const Vec3 across = axis.cross(Vec3::UnitZ()).normalized();
    double lo = 1e300, hi = -1e300;
    for (const auto& c : scene.blocks.at(size_t(a)).corners) lo = std::min(lo, c.dot(axis)), hi = std::max(hi, c.dot(axis));
    oracle::WinklerRocking w{2.0 * hb.b, 2.0 * hb.h, hi - lo, block_mass(scene, a), gravity(scene),
                             scene.contact.kn, scene.contact.ks, scene.contact.friction};
    w.zeta = scene.contact.damping_rule == ContactDampingRule::ratio ? scene.contact.damping : 0.0;
    int div_across = 1;
    for (int k = 0; k < 3; ++k)
        if (std::abs(across[k]) > 0.5) div_across = contact.divisions[size_t(k)];
    w.cells_across = div_across * scene.contact.subdivision;
    w.cells_up = contact.divisions[2] * scene.contact.subdivision;
    return w;
}

std::string winkler_unmodelled(const Scene& scene, ContactKind contact, const Vec3& axis) {
    if (!contact.penalty) return "rigid contact: Housner's rigid base, not a Winkler bed";
    if (!contact.point_springs) return "an engine's matched contact reproduces kn·A of a face, not the Winkler integral under a pivoting corner";
    if (scene.contact.scheme != ContactScheme::overlap)
        return "the paper scheme lumps kn on grid points (an edge row's stiffness set by the grid), not the Winkler integral";
    if (scene.contact.damping_rule == ContactDampingRule::time) return "the oracle carries dashpots by damping ratio, not by damping time";
    const auto w = winkler_model(scene, contact, axis);
    if (w.cells_across + 2 * w.cells_up > oracle::WinklerRocking::max_cells)
        return "the mesh times the sub-division cuts the faces finer than the oracle's " +
               std::to_string(oracle::WinklerRocking::max_cells) + " cells";
    return "";
}

std::vector<double> winkler_angles(const oracle::WinklerTrace& tr, const std::vector<double>& t) {
    const metrics::Series theta{tr.t, tr.theta};
    std::vector<double> out;
    out.reserve(t.size());
    for (double x : t) out.push_back(metrics::interpolate(theta, x));
    return out;
}

}  // namespace cairn::cases
