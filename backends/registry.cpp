#include "registry.hpp"

#include "dem/dem_backend.hpp"
#include "error.hpp"
#ifdef CAIRN_WITH_BULLET
#include "bullet/bullet_backend.hpp"
#endif
#ifdef CAIRN_WITH_ODE
#include "ode/ode_backend.hpp"
#endif
#ifdef CAIRN_WITH_MUJOCO
#include "mujoco/mujoco_backend.hpp"
#endif
#ifdef CAIRN_WITH_SICONOS
#include "siconos/siconos_backend.hpp"
#endif

namespace cairn {

const std::vector<BackendInfo>& available_backends() {
    static const std::vector<BackendInfo> list = [] {
        std::vector<BackendInfo> l;
        l.push_back(dem_backend_info());
#ifdef CAIRN_WITH_BULLET
        l.push_back(bullet_backend_info());
#endif
#ifdef CAIRN_WITH_ODE
        l.push_back(ode_backend_info());
#endif
#ifdef CAIRN_WITH_MUJOCO
        l.push_back(mujoco_backend_info());
#endif
#ifdef CAIRN_WITH_SICONOS
        l.push_back(siconos_backend_info());
#endif
        return l;
    }();
    return list;
}

std::unique_ptr<Backend> make_backend(const std::string& name) {
    std::string names;
    for (const auto& b : available_backends()) {
        if (b.name == name) return b.make();
        names += (names.empty() ? "" : ", ") + b.name;
    }
    throw Error("unknown backend '" + name + "' (available: " + names + ")");
}

}  // namespace cairn
