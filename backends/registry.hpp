#pragma once
/// The backends built into this binary, by name.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backend/backend.hpp"

namespace cairn {

/// One available backend.
struct BackendInfo {
    std::string name;                           ///< "dem", "bullet", "ode", "mujoco"
    std::string description;                    ///< one line
    std::vector<FeatureSupport> capabilities;   ///< the capability matrix row
    std::function<std::unique_ptr<Backend>()> make;
};

/// every backend built, in a fixed order
const std::vector<BackendInfo>& available_backends();

/// a new backend by name; throws cairn::Error naming the available ones for an unknown name
std::unique_ptr<Backend> make_backend(const std::string& name);

}  // namespace cairn
