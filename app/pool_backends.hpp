#pragma once
/// Backends for a pool of jobs that share the machine's cores.

#include "validation/run_cases.hpp"

namespace cairn {

/// the backend factory of a pool of `jobs` worker threads: with more than one job, the OpenMP
/// regions of each job (dem's contact and element loops) run on the job's own thread only, so
/// that jobs × threads never exceed the cores and no team spins against another job
validation::BackendFactory pool_backend_factory(int jobs);

}  // namespace cairn
