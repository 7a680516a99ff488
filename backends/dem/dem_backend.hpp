#pragma once
/// The in-house discrete element engine as a cairn backend ("dem").

#include "backend/backend.hpp"
#include "backend/backend_info.hpp"

namespace cairn {

/// registry entry of the in-house engine
BackendInfo dem_backend_info();

}  // namespace cairn
