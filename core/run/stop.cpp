#include "run/stop.hpp"

#include <atomic>
#include <csignal>
#include <initializer_list>

namespace cairn {

namespace {

std::atomic<bool> g_stop{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the stop flag is set from a signal handler");

extern "C" void on_stop_signal(int) { g_stop.store(true, std::memory_order_relaxed); }

}  // namespace

void request_stop() noexcept { g_stop.store(true, std::memory_order_relaxed); }

bool stop_requested() noexcept { return g_stop.load(std::memory_order_relaxed); }

void clear_stop() noexcept { g_stop.store(false, std::memory_order_relaxed); }

void install_stop_handlers() {
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;   // the second signal takes the default action: exit at once
    for (int sig : {SIGINT, SIGTERM}) {
        // a signal ignored at start stays ignored (a background job must not stop on the
        // terminal's Ctrl-C)
        struct sigaction old {};
        if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        sigaction(sig, &sa, nullptr);
    }
}

}  // namespace cairn
