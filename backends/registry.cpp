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

namespace {

std::vector<BackendInfo>& list() {
    static std::vector<BackendInfo> l = [] {
        std::vector<BackendInfo> v;
        v.push_back(dem_backend_info());
#ifdef CAIRN_WITH_BULLET
        v.push_back(bullet_backend_info());
#endif
#ifdef CAIRN_WITH_ODE
        v.push_back(ode_backend_info());
#endif
#ifdef CAIRN_WITH_MUJOCO
        v.push_back(mujoco_backend_info());
#endif
#ifdef CAIRN_WITH_SICONOS
        v.push_back(siconos_backend_info());
#endif
        return v;
    }();
    return l;
}

std::string names() {
    std::string s;
    for (const auto& b : list()) s += (s.empty() ? "" : ", ") + b.name;
    return s;
}

}  // namespace

const std::vector<BackendInfo>& available_backends() { return list(); }

void register_backend(BackendInfo info) {
    if (!info.make) throw Error("backend '" + info.name + "': no make function");
    for (const auto& b : list())
        if (b.name == info.name) throw Error("backend '" + info.name + "' is registered already");
    list().push_back(std::move(info));
}

std::unique_ptr<Backend> make_backend(const std::string& name) { return find_backend(list(), name).make(); }

void check_backend_tables(const Scene& scene, const std::string& path) {
    for (const auto& [name, settings] : scene.backend_settings) {
        bool known = false;
        for (const auto& b : list()) known = known || b.name == name;
        if (known) continue;
        // a setting's origin is "file:line"; an empty table has only the file
        const std::string where = settings.empty() ? path : settings.begin()->second.origin;
        throw Error(where + ": backends." + name + ": unknown backend (available: " + names() + ")");
    }
}

}  // namespace cairn
