#pragma once
/// Bullet 3 (btDiscreteDynamicsWorld, double precision) as a cairn backend ("bullet").

#include "backend/backend.hpp"
#include "backend/backend_info.hpp"

namespace cairn {

/// registry entry of the Bullet backend: name, description, capability matrix row, factory
BackendInfo bullet_backend_info();

}  // namespace cairn
