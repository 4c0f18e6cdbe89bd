#pragma once
// Seconds per phase of the step loop (epac-run --phase-times): each lap fences the device (so
// asynchronous backends charge a kernel to the phase that launched it; on host backends
// parallel_for is synchronous anyway) and charges the time since the previous lap to a phase.
// Disabled: lap() does nothing (no fences, no clock reads): the loop runs as without the flag.
#include <Kokkos_Core.hpp>

#include <array>
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace epac {
namespace driver {

enum class Phase : int { detection = 0, remap, force, growth, integration, output, count };

class PhaseTimer {
 public:
  explicit PhaseTimer(bool enabled) : enabled_(enabled) {}
  bool enabled() const { return enabled_; }

  // Laps before start() (the setup's force pass) are not counted.
  void start() {
    if (!enabled_) return;
    running_ = true;
    Kokkos::fence();
    mark_ = clock::now();
  }
  // Charges the time since the last lap (or start) to `ph`.
  void lap(Phase ph) {
    if (!running_) return;
    Kokkos::fence();
    const auto now = clock::now();
    seconds_[static_cast<int>(ph)] += std::chrono::duration<double>(now - mark_).count();
    mark_ = now;
  }

  // (name, seconds) in the order of the enum: the keys of summary.json "phases".
  std::vector<std::pair<std::string, double>> results() const {
    static const char* names[] = {"detection", "remap", "force", "growth", "integration", "output"};
    std::vector<std::pair<std::string, double>> r;
    for (int k = 0; k < static_cast<int>(Phase::count); ++k) r.emplace_back(names[k], seconds_[k]);
    return r;
  }

 private:
  using clock = std::chrono::steady_clock;
  bool enabled_;
  bool running_ = false;
  clock::time_point mark_{};
  std::array<double, static_cast<int>(Phase::count)> seconds_{};
};

}  // namespace driver
}  // namespace epac
