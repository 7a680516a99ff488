#include "backend/backend_info.hpp"

#include "error.hpp"

namespace cairn {

const BackendInfo& find_backend(const std::vector<BackendInfo>& list, const std::string& name) {
    std::string names;
    for (const auto& b : list) {
        if (b.name == name) return b;
        names += (names.empty() ? "" : ", ") + b.name;
    }
    throw Error("unknown backend '" + name + "' (available: " + names + ")");
}

}  // namespace cairn
