#include "driver/stop_signal.hpp"

#include <csignal>
#include <cstring>
#include <ctime>

namespace epac {
namespace driver {
namespace {

// Both written only inside the handler, which blocks SIGINT and SIGTERM while it runs.
volatile std::sig_atomic_t g_signal = 0;
volatile long long g_first_ns = 0;  // CLOCK_MONOTONIC time of the recorded request

// The same signal again within this window is the same request delivered twice: coreutils
// `timeout` signals the child and then its own process group, and batch schedulers signal the
// job's process group, so one stop request can arrive as two signals microseconds apart.
constexpr long long kDuplicateWindowNs = 500000000LL;  // 0.5 s: shorter than a person's second Ctrl-C

long long monotonic_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);  // async-signal-safe (POSIX)
  return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

extern "C" void record_signal(int sig) {
  const long long now = monotonic_ns();
  if (g_signal == 0) {
    g_first_ns = now;
    g_signal = sig;
    return;
  }
  if (sig == g_signal && now - g_first_ns < kDuplicateWindowNs) return;  // a duplicate, not a second request
  // A second request: the default action ends the process as soon as the handler returns.
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

void install_stop_handlers() {
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = record_signal;
  sigemptyset(&sa.sa_mask);
  sigaddset(&sa.sa_mask, SIGINT);  // the handler never interrupts itself
  sigaddset(&sa.sa_mask, SIGTERM);
  sa.sa_flags = 0;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

int stop_signal() { return g_signal; }

void clear_stop_signal() {
  g_signal = 0;
  g_first_ns = 0;
}

}  // namespace driver
}  // namespace epac
