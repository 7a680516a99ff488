#include "pool_backends.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

#include "registry.hpp"

namespace cairn {

validation::BackendFactory pool_backend_factory(int jobs) {
    const bool one_thread = jobs > 1;
    return [one_thread](const std::string& name) {
#ifdef _OPENMP
        // called on the pool thread that runs the job: its OpenMP regions then use one thread
        if (one_thread) omp_set_num_threads(1);
#else
        (void)one_thread;
#endif
        return make_backend(name);
    };
}

}  // namespace cairn
