#pragma once
// Helpers of the driver tests: a fresh output folder, timeseries CSVs by column, a scene run.
#include "driver/csv_columns.hpp"
#include "driver/model_registry.hpp"
#include "driver/scene.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

namespace epac {
namespace test {

// Removed first: a folder left by an earlier test process with the same pid would hold another
// run's outputs, which the driver refuses.
inline std::filesystem::path fresh_out_dir(const std::string& tag) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() /
                   ("epac-driver-" + std::to_string(getpid()) + "-" + tag + "-" + std::to_string(counter++));
  std::filesystem::remove_all(dir);
  return dir;
}

// A CSV with a header line, as columns by name without the unit ("time [s]" -> "time"); a text
// cell (contacts.csv's wall_name) reads as NaN.
inline std::map<std::string, std::vector<double>> read_csv_columns(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  {
    std::stringstream s(line);
    std::string c;
    while (std::getline(s, c, ',')) names.push_back(driver::csv_column_name(c));  // without the unit
  }
  std::map<std::string, std::vector<double>> cols;
  for (const auto& n : names) cols[n];
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string c;
    for (const auto& n : names) {
      std::getline(s, c, ',');
      char* end = nullptr;
      const double v = std::strtod(c.c_str(), &end);
      cols[n].push_back(end != c.c_str() ? v : std::nan(""));  // a text cell (wall_name): NaN
    }
  }
  return cols;
}

inline driver::RunSummary run_scene_text(const std::string& text, const std::filesystem::path& dir,
                                         const std::string& precision = "double") {
  driver::RunOptions opt;
  opt.out_dir = dir.string();
  opt.quiet = true;
  opt.precision = precision;
  return driver::run(driver::parse_scene_string(text, "test.toml"), opt);
}

inline double counter_of(const driver::RunSummary& s, const std::string& name) {
  for (const auto& kv : s.model_counters)
    if (kv.first == name) return kv.second;
  return -1.0;
}

}  // namespace test
}  // namespace epac
