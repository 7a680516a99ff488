#pragma once
/// Writing trajectories: t, probes, free blocks' pose, energies, contact count.

#include <ostream>
#include <string>
#include <vector>

#include "backend/backend.hpp"

namespace cairn {

/// column names: t, P.x,P.y,P.z per probe, B.x..B.qz per free block, energies, contacts
std::vector<std::string> trajectory_columns(const Scene& scene);

/// write the header and one row per sample, with 17 significant digits
void write_trajectory_csv(std::ostream& out, const Scene& scene, const std::vector<Sample>& samples);

}  // namespace cairn
