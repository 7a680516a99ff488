#pragma once
/// OpenMP threads that wait for work sleep instead of spinning, unless the environment says
/// otherwise (docs/architecture.md, The run layer).

namespace cairn {

/// unless OMP_WAIT_POLICY or GOMP_SPINCOUNT is set, set OMP_WAIT_POLICY=passive and start this
/// executable again with the same arguments (libgomp reads its environment once, when it is
/// loaded, before main); returns only when nothing was to be done or the restart failed
void ensure_passive_openmp_wait(char** argv);

}  // namespace cairn
