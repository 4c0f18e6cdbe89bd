#pragma once
// SIGINT / SIGTERM: the run stops at the end of the current step and writes whole outputs with
// summary.json status "interrupted" (run_scene.hpp). The handler only records the signal (an
// async-signal-safe store to a sig_atomic_t); SA_RESETHAND makes a second signal act as usual,
// so a second Ctrl-C ends a run that does not reach the end of its step.
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
