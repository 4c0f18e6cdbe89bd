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
  TimeseriesWriter(const std::string& path, const std::vector<std::string>& wall_names, bool driven_columns);
  void write(const Sample& s);

 private:
  std::ofstream out_;
  bool driven_;
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
