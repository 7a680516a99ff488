#pragma once
/// The backends built into this binary, by name: the only place that lists the engines. A new
/// backend is its folder, its CMake block and one line of registry.cpp.

#include <memory>
#include <string>
#include <vector>

#include "backend/backend_info.hpp"
#include "scene/scene.hpp"

namespace cairn {

/// every backend built, in a fixed order (then any added by register_backend)
const std::vector<BackendInfo>& available_backends();

/// add a backend after the built ones (a test double of the test build); throws cairn::Error on a
/// name taken or without a make function. Call before handing available_backends() to a pool.
void register_backend(BackendInfo info);

/// a new backend by name; throws cairn::Error naming the available ones for an unknown name
std::unique_ptr<Backend> make_backend(const std::string& name);

/// throws cairn::Error when `scene` has a [backends.NAME] table of no available backend, naming the
/// file (or `path` when the table holds no setting), the table and the available backends
void check_backend_tables(const Scene& scene, const std::string& path);

}  // namespace cairn
