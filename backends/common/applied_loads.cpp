#include "applied_loads.hpp"

namespace cairn {

void applied_loads(const Scene& scene, double t, std::vector<AppliedLoad>& out) {
    out.clear();
    for (const LoadDef& l : scene.loads) {
        const double f = l.factor(t);
        if (f == 0.0 || scene.blocks[size_t(l.block)].fixed) continue;
        out.push_back({l.block, f * l.force, l.point});
    }
}

double load_power(const std::vector<AppliedLoad>& loads,
                  const std::function<Vec3(int block, const Vec3& point)>& point_velocity) {
    double power = 0.0;
    for (const AppliedLoad& l : loads) power += l.force.dot(point_velocity(l.block, l.point));
    return power;
}

}  // namespace cairn
