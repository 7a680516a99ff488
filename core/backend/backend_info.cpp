#include "backend/backend_info.hpp"

#include "error.hpp"

namespace cairn {

Support support_of(const BackendInfo& backend, Feature feature) {
    for (const auto& f : backend.capabilities)
        if (f.feature == feature) return f.support;
    return Support::none;
}

const BackendInfo& find_backend(const std::vector<BackendInfo>& list, const std::string& name) {
    std::string names;
    for (const auto& b : list) {
        if (b.name == name) return b;
        names += (names.empty() ? "" : ", ") + b.name;
    }
    throw Error("unknown backend '" + name + "' (available: " + names + ")");
}

}  // namespace cairn
