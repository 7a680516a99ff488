#pragma once
/// Differences between two runs of the same case (e.g. deformable vs rigid DEM vs Bullet).

#include <vector>

#include "backend/backend.hpp"

namespace cairn::metrics {

/// RMS distance (m) between the paths of probe `p` in run `a` and run `b`, with a's time shifted:
/// a(t + shift) against b(t) over the times of b that a covers
double probe_path_rms(const std::vector<Sample>& a, const std::vector<Sample>& b, int p, double shift);

}  // namespace cairn::metrics
