#pragma once
/// A stop asked for from outside a run (SIGINT, SIGTERM): runs end at their next step boundary with
/// status interrupted, and the commands that run many of them start no new one.

namespace cairn {

/// ask every run to stop; safe to call from a signal handler
void request_stop() noexcept;

/// true once a stop was asked for
bool stop_requested() noexcept;

/// forget an earlier request (tests)
void clear_stop() noexcept;

/// send SIGINT and SIGTERM to request_stop(); a second signal ends the process at once (the
/// default action), which never leaves a half-written result in place since results are swapped
/// in whole (output/staged_dir.hpp); a signal ignored when the process started stays ignored
void install_stop_handlers();

}  // namespace cairn
