#include "backend_option.hpp"

#include <algorithm>

#include "error.hpp"
#include "registry.hpp"
#include "suggest.hpp"

namespace cairn {

std::vector<std::string> chosen_backends(const std::vector<std::string>& given) {
    std::vector<std::string> names;
    for (const auto& b : available_backends()) names.push_back(b.name);
    if (given.empty() || (given.size() == 1 && given[0] == "all")) return names;
    for (const auto& b : given)
        if (std::find(names.begin(), names.end(), b) == names.end()) {
            std::string all;
            for (const auto& n : names) all += (all.empty() ? "" : ",") + n;
            throw Error("--backends " + b + ": no such backend" + did_you_mean(b, names) + "; available: " + all);
        }
    return given;
}

std::vector<BackendInfo> backend_infos(const std::vector<std::string>& names) {
    std::vector<BackendInfo> out;
    for (const auto& n : names) out.push_back(find_backend(available_backends(), n));
    return out;
}

}  // namespace cairn
