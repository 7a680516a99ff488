#pragma once
/// MuJoCo 2.2.2 as a cairn backend ("mujoco"); the model is MJCF text built in memory.

#include "backend/backend.hpp"
#include "backend/backend_info.hpp"

namespace cairn {

/// registry entry of the MuJoCo backend: name, description, capability matrix row, factory
BackendInfo mujoco_backend_info();

}  // namespace cairn
