#pragma once
// SIGINT / SIGTERM: the run stops at the end of the current step and writes whole outputs with
// summary.json status "interrupted" (run_scene.hpp). The handler only records the signal (an
// async-signal-safe store to a sig_atomic_t). A second request ends the process at once (the
// signal's default action), so a second Ctrl-C ends a run that does not reach the end of its step;
// the same signal again within 0.5 s is the same request delivered twice (coreutils `timeout` and
// batch schedulers signal the process and then its process group) and is ignored.
namespace epac {
namespace driver {

// Installs the handler for SIGINT and SIGTERM (epac-run's main; library users keep their own).
void install_stop_handlers();
// The signal that asked the run to stop, 0 if none.
int stop_signal();
// Tests: forget a recorded signal.
void clear_stop_signal();

}  // namespace driver
}  // namespace epac
