#pragma once
/// The Open Dynamics Engine (0.16, double precision) as a cairn backend ("ode").

#include "backend/backend.hpp"
#include "backend/backend_info.hpp"

namespace cairn {

/// registry entry of the ODE backend: name, description, capability matrix row, factory
BackendInfo ode_backend_info();

}  // namespace cairn
