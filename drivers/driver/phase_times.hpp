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
  // The start of the --time-after window: charges the time since the last lap to `ph` and
  // remembers the totals, so window_results() are the window's phases alone (the loop's totals
  // mix the box deformation's steps into a hold phase's).
  void mark_window(Phase ph) {
    if (!running_) return;
    lap(ph);
    at_window_ = seconds_;
    window_ = true;
  }

  // (name, seconds) in the order of the enum: the keys of summary.json "phases".
  std::vector<std::pair<std::string, double>> results() const { return named(seconds_, {}); }
  // Since mark_window() (empty if it never ran): summary.json "timed" "phases".
  std::vector<std::pair<std::string, double>> window_results() const {
    if (!window_) return {};
    return named(seconds_, at_window_);
  }

 private:
  using clock = std::chrono::steady_clock;
  using Seconds = std::array<double, static_cast<int>(Phase::count)>;
  static std::vector<std::pair<std::string, double>> named(const Seconds& s, const Seconds& minus) {
    static const char* names[] = {"detection", "remap", "force", "growth", "integration", "output"};
    std::vector<std::pair<std::string, double>> r;
    for (int k = 0; k < static_cast<int>(Phase::count); ++k) r.emplace_back(names[k], s[k] - minus[k]);
    return r;
  }
  bool enabled_;
  bool running_ = false;
  clock::time_point mark_{};
  Seconds seconds_{}, at_window_{};
  bool window_ = false;
};

}  // namespace driver
}  // namespace epac
