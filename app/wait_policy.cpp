#include "wait_policy.hpp"

#include <unistd.h>

#include <cstdlib>

namespace cairn {

void ensure_passive_openmp_wait(char** argv) {
    // a spinning team slows down anything else that wants its cores: structures/arch on dem took
    // 60-160 s spinning against 1-2 s passive on a busy 2-core machine
    if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
    if (setenv("OMP_WAIT_POLICY", "passive", 0) != 0) return;
    execv("/proc/self/exe", argv);   // on success never returns; on failure run as we are
}

}  // namespace cairn
