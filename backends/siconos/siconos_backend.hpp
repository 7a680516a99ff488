#pragma once
/// Siconos 4.4 (non-smooth contact dynamics) as a cairn backend ("siconos"): Moreau–Jean time
/// stepping, Signorini contact and Coulomb friction as a 3-D friction-contact problem, Newton
/// impact law.

#include "backend/backend.hpp"
#include "backend/backend_info.hpp"

namespace cairn {

/// registry entry of the Siconos backend: name, description, capability matrix row, factory
BackendInfo siconos_backend_info();

}  // namespace cairn
