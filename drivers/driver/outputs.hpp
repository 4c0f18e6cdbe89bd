#pragma once
// Run outputs: timeseries.csv, summary.json and the terminal progress line, and the rules of the
// output folder. Every file is written under a temporary name (NAME.partial) in its folder and
// renamed when it is whole; summary.json is renamed last, so a folder with summary.json holds one
// run's complete files, and a NAME.partial is a file of a run that is still going or was killed.
#include "driver/run_options.hpp"
#include "driver/sample.hpp"

#include <epac/params/validation.hpp>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace epac {
namespace driver {

// Creates the output folder (and parents). Throws std::runtime_error when it cannot.
void make_output_dir(const std::string& dir);

// The suffix of a file being written; the file gets its name when it is whole.
constexpr const char* kPartialSuffix = ".partial";

// The epac-run outputs already in `dir` (paths; .partial files and snapshots/particles_*.vtp
// included), other files not: timeseries.csv, summary.json, contacts.csv, particles.csv,
// particles.pvd, snapshots/particles_*.vtp.
std::vector<std::string> outputs_in(const std::string& dir);

// A refused output folder (exit status 2, like other input errors).
class OutputFolderInUse : public ParameterError {
 public:
  using ParameterError::ParameterError;
};

// Creates `dir` for a new run. A folder that holds outputs of another run is refused
// (OutputFolderInUse) unless `overwrite`: then those outputs, and nothing else, are removed
// first (an emptied snapshots/ too), so the folder never mixes two runs' files.
void prepare_output_dir(const std::string& dir, bool overwrite);

// A text file written under PATH.partial and renamed to PATH by commit() (same folder, so the
// rename is atomic on POSIX): a reader never sees a cut file under the final name.
class StagedFile {
 public:
  explicit StagedFile(const std::string& path);
  std::ofstream& stream() { return out_; }
  // Flushes, closes and renames; throws std::runtime_error on a write error.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ofstream out_;
  bool committed_ = false;
};

// Writes `text` to PATH.partial and renames it to PATH.
void write_file_atomic(const std::string& path, const std::string& text);

// timeseries.csv: one header line, then one row per sample; columns in drivers/README.md.
class TimeseriesWriter {
 public:
  TimeseriesWriter(const std::string& path, const std::vector<std::string>& wall_names, bool driven_columns,
                   bool box_columns = false);
  void write(const Sample& s);
  void commit() { file_.commit(); }  // the file gets its name (the end of the run)

 private:
  StagedFile file_;
  std::ofstream& out_;
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
  std::vector<double> extras;  // row-major, extra_count per row
  int extra_count = 0;
};
class ContactsWriter {
 public:
  ContactsWriter(const std::string& path, const std::vector<std::string>& extra_names,
                 const std::vector<std::string>& wall_names);
  void write(std::int64_t step, double time, const ContactRows& rows);
  void commit() { file_.commit(); }

 private:
  StagedFile file_;
  std::ofstream& out_;
  std::vector<std::string> walls_;
};

// particles.csv ([run] particle_output): step, time, id, x, y, z, R, R0, volume.
class ParticlesWriter {
 public:
  explicit ParticlesWriter(const std::string& path);
  void write(std::int64_t step, double time, const std::vector<double>& x, const std::vector<double>& y,
             const std::vector<double>& z, const std::vector<double>& R, const std::vector<double>& R0,
             const std::vector<double>& V);
  void commit() { file_.commit(); }

 private:
  StagedFile file_;
  std::ofstream& out_;
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
