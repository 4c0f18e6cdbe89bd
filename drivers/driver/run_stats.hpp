#pragma once
// The counters of one run (run_scene.hpp) from which summary.json gets its means and rates: steps
// done, list entries per step, active contacts per sample, and the same for the --time-after
// window (the steps after N alone).
#include <cstdint>

namespace epac {
namespace driver {

struct RunStats {
  std::int64_t done = 0;     // steps completed (their forces and outputs written)
  std::int64_t builds0 = 0;  // contact detections before the loop: rebuilds = builds - builds0
  double list_steps = 0;     // list entries (pairs + walls), summed over the steps
  double active_sum = 0;     // active contacts (overlap > 0), summed over the samples
  std::int64_t samples = 0;
  // --time-after window: the same sums over its steps and samples
  double window_list_steps = 0, window_active_sum = 0;
  std::int64_t window_samples = 0;

  // One step's list entries.
  void add_step(int list_entries, bool in_window) {
    list_steps += list_entries;
    if (in_window) window_list_steps += list_entries;
  }
  // One sample's active contacts.
  void add_sample(std::int64_t active, bool in_window) {
    active_sum += static_cast<double>(active);
    ++samples;
    if (in_window) {
      window_active_sum += static_cast<double>(active);
      ++window_samples;
    }
  }
};

}  // namespace driver
}  // namespace epac
