#pragma once
// Run outputs: timeseries.csv, summary.json and the terminal progress line.
#include "driver/run_options.hpp"
#include "driver/sample.hpp"

#include <chrono>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace epac {
namespace driver {

// Creates the output folder (and parents). Throws std::runtime_error when it cannot.
void make_output_dir(const std::string& dir);

// timeseries.csv: one header line, then one row per sample; columns in drivers/README.md.
class TimeseriesWriter {
 public:
  TimeseriesWriter(const std::string& path, const std::vector<std::string>& wall_names, bool driven_columns,
                   bool box_columns = false);
  void write(const Sample& s);

 private:
  std::ofstream out_;
  bool driven_;
  bool box_;
};

// contacts.csv ([run] contact_output): one row per interacting contact per output step.
// Columns: step, time, i, j (global ids; j = -1 for a wall), wall (index, -1 for a pair),
// wall_name, overlap, force (normal, law + damping, > 0 compressive), then the model's extras.
struct ContactRows {
  std::vector<std::int64_t> i, j;  // global ids; j = -1 for a wall contact
  std::vector<int> wall;           // wall index, -1 for a pair
  std::vector<double> overlap, force;
  std::vector<double> extras;      // row-major, extra_count per row
  int extra_count = 0;
};
class ContactsWriter {
 public:
  ContactsWriter(const std::string& path, const std::vector<std::string>& extra_names,
                 const std::vector<std::string>& wall_names);
  void write(std::int64_t step, double time, const ContactRows& rows);

 private:
  std::ofstream out_;
  std::vector<std::string> walls_;
};

// particles.csv ([run] particle_output): step, time, id, x, y, z, R, R0, volume.
class ParticlesWriter {
 public:
  explicit ParticlesWriter(const std::string& path);
  void write(std::int64_t step, double time, const std::vector<double>& x, const std::vector<double>& y,
             const std::vector<double>& z, const std::vector<double>& R, const std::vector<double>& R0,
             const std::vector<double>& V);

 private:
  std::ofstream out_;
};

void write_summary_json(const std::string& path, const RunSummary& s);

// A single \r-refreshed line with rate and ETA, at most every 0.25 s; silent when disabled.
class ProgressLine {
 public:
  ProgressLine(bool enabled, std::int64_t total_steps);
  void update(std::int64_t step, double contact_steps);
  void finish();

 private:
  using clock = std::chrono::steady_clock;
  bool enabled_;
  std::int64_t total_;
  clock::time_point start_, last_;
  bool printed_ = false;
};

}  // namespace driver
}  // namespace epac
