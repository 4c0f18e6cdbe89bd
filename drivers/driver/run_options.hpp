#pragma once
// What the command line adds to a scene, and what a run reports (summary.json).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace epac {
namespace driver {

// The divergence watch stopped the run (diagnostics.hpp); the outputs, summary.json with status
// "diverged" included, are whole when it is thrown. epac-run exits 3.
class DivergedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunOptions {
  std::string out_dir = "epac-out";
  std::int64_t steps = -1;           // >= 0 overrides [run] steps
  std::string precision = "double";  // "double" | "float"
  bool quiet = false;                // no informational lines, no progress line
  bool progress = false;             // the \r progress line (main sets it when stdout is a terminal)
  bool phase_times = false;          // --phase-times: seconds per loop phase in summary.json "phases"
  std::int64_t time_after = -1;      // --time-after N: also time steps N+1.. alone (summary.json "timed")
  bool overwrite = false;            // --overwrite: replace the epac outputs of an earlier run in out_dir
  bool deterministic = false;        // --deterministic: as [run] deterministic = true (either turns it on)
};

// How the contact history started ([run] initial_history, driver/initial_history.hpp).
struct InitialHistorySummary {
  std::string mode = "zero";     // what was done: "from_overlaps" or "zero"
  bool applied = false;          // history_from_overlaps ran
  int overlapping_contacts = 0;  // contacts overlapping at step 0
  double max_overlap_ratio = 0;  // largest overlap / min(R_o) at step 0
  int increments = 0;            // load increments (applied only)
  double max_radius_ratio = 1;   // largest R / R_o after the load (MDR growth)
  long long guard_hits = 0;      // growth-guard hits during the load
};

struct RunSummary {
  // "completed", "diverged" (the divergence watch stopped it; status_reason says which particle,
  // quantity, value and bound) or "interrupted" (SIGINT/SIGTERM; stop_signal is the signal).
  std::string status = "completed";
  std::string status_reason;
  int stop_signal = 0;
  std::int64_t steps_completed = 0;  // steps whose outputs were written (== steps when completed)
  std::string scene, model, effects, scalar, backend;
  int threads = 0;
  std::int64_t particles = 0, walls = 0, steps = 0, rebuilds = 0;
  std::int64_t sorts = 0;  // spatial sorts ([run] spatial_sort), the one at setup included
  double dt = 0, simulated_time = 0;
  double wall_time_s = 0;                      // the stepping loop only
  double setup_time_s = 0;                     // device state, first detection and forces
  double contacts_mean = 0;                    // active contacts (overlap > 0), mean over output samples
  double contact_list_mean = 0;                // entries of the pair + wall lists, mean over steps
  double contact_steps_per_second = 0;         // list entries evaluated per second of wall time
  double active_contact_steps_per_second = 0;  // contacts_mean x steps / wall time
  double particle_steps_per_second = 0;        // particles x steps / wall time
  // --phase-times: seconds per phase of the loop (driver/phase_times.hpp); empty otherwise
  // (then summary.json has no "phases").
  std::vector<std::pair<std::string, double>> phases;
  // --time-after N: the steps after N alone (e.g. the hold phase after a box deformation), so a
  // benchmark can time the same window as a peer code's last `run`.
  struct TimedWindow {
    bool enabled = false;
    std::int64_t first_step = 0, steps = 0;
    double wall_s = 0;
    double list_contacts_mean = 0;    // list entries per step
    double active_contacts_mean = 0;  // overlapping contacts, mean over the window's output samples
    // with --phase-times: the window's seconds per phase ("timed" "phases"); empty otherwise
    std::vector<std::pair<std::string, double>> phases;
  } timed;
  // With a [box]: the edges at the end of the run [m] (summary.json "box_edge"); empty otherwise.
  std::vector<double> box_edge;
  int history_fields = 0;
  std::size_t bytes_per_contact = 0;
  std::string timeseries_path, summary_path;
  // Model-specific counters (ModelFactoryBase::report), e.g. MDR guard hits; in summary.json.
  std::vector<std::pair<std::string, double>> model_counters;
  InitialHistorySummary initial_history;
  std::vector<std::string> warnings;  // also printed to stderr; summary.json "warnings"
};

}  // namespace driver
}  // namespace epac
