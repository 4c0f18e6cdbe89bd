#include "driver/outputs.hpp"

#include <epac/core/build_info.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <stdexcept>

namespace epac {
namespace driver {

void make_output_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw std::runtime_error("cannot create the output folder '" + dir + "': " + ec.message());
}

namespace {

const char* const kOutputNames[] = {"timeseries.csv", "summary.json", "contacts.csv", "particles.csv", "particles.pvd"};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// snapshots/particles_<step>.vtp, finished or not.
bool is_snapshot_name(const std::string& name) {
  std::string n = name;
  if (ends_with(n, kPartialSuffix)) n.resize(n.size() - std::string(kPartialSuffix).size());
  return n.compare(0, 10, "particles_") == 0 && ends_with(n, ".vtp");
}

}  // namespace

std::vector<std::string> outputs_in(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<std::string> found;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return found;
  for (const char* name : kOutputNames)
    for (const std::string& f : {std::string(name), std::string(name) + kPartialSuffix})
      if (fs::exists(fs::path(dir) / f, ec)) found.push_back((fs::path(dir) / f).string());
  const fs::path snaps = fs::path(dir) / "snapshots";
  if (fs::is_directory(snaps, ec))
    for (const auto& e : fs::directory_iterator(snaps, ec))
      if (is_snapshot_name(e.path().filename().string())) found.push_back(e.path().string());
  return found;
}

void prepare_output_dir(const std::string& dir, bool overwrite) {
  namespace fs = std::filesystem;
  const std::vector<std::string> old = outputs_in(dir);
  if (!old.empty() && !overwrite) {
    std::string names;
    for (std::size_t k = 0; k < old.size() && k < 4; ++k)
      names += (k ? ", " : "") + fs::path(old[k]).lexically_relative(dir).string();
    if (old.size() > 4) names += ", ... (" + std::to_string(old.size()) + " files)";
    throw OutputFolderInUse("--out = '" + dir + "' holds outputs of another run (" + names +
                            "); give another --out folder, or --overwrite to remove those outputs first");
  }
  for (const auto& f : old) {
    std::error_code ec;
    fs::remove(f, ec);
    if (ec) throw std::runtime_error("cannot remove the old output '" + f + "': " + ec.message());
  }
  std::error_code ec;
  const fs::path snaps = fs::path(dir) / "snapshots";
  if (fs::is_directory(snaps, ec) && fs::is_empty(snaps, ec)) fs::remove(snaps, ec);  // only if now empty
  make_output_dir(dir);
}

StagedFile::StagedFile(const std::string& path) : path_(path), out_(path + kPartialSuffix) {
  if (!out_) throw std::runtime_error("cannot write '" + path + kPartialSuffix + "'");
}

void StagedFile::commit() {
  if (committed_) return;
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok) throw std::runtime_error("cannot write '" + path_ + kPartialSuffix + "'");
  std::error_code ec;
  std::filesystem::rename(path_ + kPartialSuffix, path_, ec);
  if (ec)
    throw std::runtime_error("cannot rename '" + path_ + kPartialSuffix + "' to '" + path_ + "': " + ec.message());
  committed_ = true;
}

void write_file_atomic(const std::string& path, const std::string& text) {
  StagedFile f(path);
  f.stream() << text;
  f.commit();
}

TimeseriesWriter::TimeseriesWriter(const std::string& path, const std::vector<std::string>& walls, bool driven,
                                   bool box)
    : file_(path), out_(file_.stream()), driven_(driven), box_(box) {
  // Units in the headers (csv_columns.hpp): SI; counts have none.
  out_ << "step,time [s],ke_translational [J],ke_rotational [J],pe_gravity [J],pair_contacts,wall_contacts,"
          "pair_list,wall_list,max_overlap_ratio [-]";
  for (const auto& w : walls) out_ << ",force_" << w << " [N],displacement_" << w << " [m]";
  if (driven_) out_ << ",driven_fx [N],driven_fy [N],driven_fz [N]";
  if (box_) out_ << ",box_lx [m],box_ly [m],box_lz [m]";
  out_ << '\n' << std::setprecision(10);
}

void TimeseriesWriter::write(const Sample& s) {
  out_ << s.step << ',' << s.time << ',' << s.ke_translational << ',' << s.ke_rotational << ',' << s.pe_gravity << ','
       << s.pair_contacts << ',' << s.wall_contacts << ',' << s.pair_list << ',' << s.wall_list << ','
       << s.max_overlap_ratio;
  for (std::size_t k = 0; k < s.wall_force.size(); ++k) out_ << ',' << s.wall_force[k] << ',' << s.wall_displacement[k];
  if (driven_) out_ << ',' << s.driven_force[0] << ',' << s.driven_force[1] << ',' << s.driven_force[2];
  if (box_) out_ << ',' << s.box_edge[0] << ',' << s.box_edge[1] << ',' << s.box_edge[2];
  out_ << '\n';
}

ContactsWriter::ContactsWriter(const std::string& path, const std::vector<std::string>& extra_names,
                               const std::vector<std::string>& wall_names)
    : file_(path), out_(file_.stream()), walls_(wall_names) {
  out_ << "step,time [s],i,j,wall,wall_name,overlap [m],force [N]";
  for (const auto& n : extra_names) out_ << ',' << n;
  out_ << '\n' << std::setprecision(10);
}

void ContactsWriter::write(std::int64_t step, double time, const ContactRows& r) {
  const int ne = r.extra_count;
  for (std::size_t k = 0; k < r.i.size(); ++k) {
    out_ << step << ',' << time << ',' << r.i[k] << ',' << r.j[k] << ',' << r.wall[k] << ','
         << (r.wall[k] >= 0 ? walls_[r.wall[k]] : std::string()) << ',' << r.overlap[k] << ',' << r.force[k];
    for (int c = 0; c < ne; ++c) out_ << ',' << r.extras[k * ne + c];
    out_ << '\n';
  }
}

ParticlesWriter::ParticlesWriter(const std::string& path) : file_(path), out_(file_.stream()) {
  out_ << "step,time [s],id,x [m],y [m],z [m],R [m],R0 [m],volume [m^3]\n" << std::setprecision(10);
}

void ParticlesWriter::write(std::int64_t step, double time, const std::vector<double>& x, const std::vector<double>& y,
                            const std::vector<double>& z, const std::vector<double>& R, const std::vector<double>& R0,
                            const std::vector<double>& V) {
  // Positions round-trip (17 digits): they are absolute, so 10 digits would keep only 1e-7 m of a
  // coordinate at 1000 m, coarser than the overlaps of mm beads; the rest are relative to themselves.
  constexpr int kPos = std::numeric_limits<double>::max_digits10;
  for (std::size_t k = 0; k < x.size(); ++k)
    out_ << step << ',' << time << ',' << k << ',' << std::setprecision(kPos) << x[k] << ',' << y[k] << ',' << z[k]
         << ',' << std::setprecision(10) << R[k] << ',' << R0[k] << ',' << V[k] << '\n';
}

void write_summary_json(const std::string& path, const RunSummary& s) {
  nlohmann::json j;
  j["status"] = s.status;  // completed | diverged | interrupted
  if (s.status != "completed") j["status_reason"] = s.status_reason;
  j["steps_completed"] = s.steps_completed;
  j["scene"] = s.scene;
  j["particles"] = s.particles;
  j["walls"] = s.walls;
  j["steps"] = s.steps;
  j["dt"] = s.dt;
  j["simulated_time"] = s.simulated_time;
  j["contacts_mean"] = s.contacts_mean;
  j["contact_list_mean"] = s.contact_list_mean;
  j["rebuilds"] = s.rebuilds;
  j["spatial_sorts"] = s.sorts;
  j["wall_time_s"] = s.wall_time_s;
  j["setup_time_s"] = s.setup_time_s;
  j["contact_steps_per_second"] = s.contact_steps_per_second;
  j["active_contact_steps_per_second"] = s.active_contact_steps_per_second;
  j["particle_steps_per_second"] = s.particle_steps_per_second;
  if (s.timed.enabled) {
    j["timed"] = {{"first_step", s.timed.first_step},
                  {"steps", s.timed.steps},
                  {"wall_s", s.timed.wall_s},
                  {"list_contacts_mean", s.timed.list_contacts_mean},
                  {"active_contacts_mean", s.timed.active_contacts_mean}};
    if (!s.timed.phases.empty()) {
      nlohmann::json ph = nlohmann::json::object();
      for (const auto& kv : s.timed.phases) ph[kv.first] = kv.second;
      j["timed"]["phases"] = ph;
    }
  }
  if (!s.phases.empty()) {
    nlohmann::json ph = nlohmann::json::object();
    for (const auto& kv : s.phases) ph[kv.first] = kv.second;
    j["phases"] = ph;
  }
  if (!s.box_edge.empty()) j["box_edge"] = s.box_edge;
  j["backend"] = s.backend;
  j["threads"] = s.threads;
  j["scalar"] = s.scalar;
  j["model"] = s.model;
  j["effects"] = s.effects;
  j["history_fields"] = s.history_fields;
  j["bytes_per_contact"] = s.bytes_per_contact;
  j["epac_version"] = epac::version_string;  // what produced this file (core/build_info.hpp)
  j["kokkos_version"] = epac::kokkos_version_string();
  j["kokkos_backends"] = epac::kokkos_backends();
  if (!s.model_counters.empty()) {
    nlohmann::json c = nlohmann::json::object();
    for (const auto& kv : s.model_counters) c[kv.first] = kv.second;
    j["model_counters"] = c;
  }
  const InitialHistorySummary& ih = s.initial_history;
  j["initial_history"] = {{"mode", ih.mode},
                          {"overlapping_contacts", ih.overlapping_contacts},
                          {"max_overlap_ratio", ih.max_overlap_ratio}};
  if (ih.applied) {
    j["initial_history"]["increments"] = ih.increments;
    j["initial_history"]["max_radius_ratio"] = ih.max_radius_ratio;
    j["initial_history"]["guard_hits"] = ih.guard_hits;
  }
  j["warnings"] = s.warnings;
  write_file_atomic(path, j.dump(2) + "\n");
}

ProgressLine::ProgressLine(bool enabled, std::int64_t total)
    : enabled_(enabled), total_(total), start_(clock::now()), last_(start_) {}

void ProgressLine::update(std::int64_t step, double contact_steps) {
  if (!enabled_) return;
  const auto now = clock::now();
  if (now - last_ < std::chrono::milliseconds(250) && step < total_) return;
  last_ = now;
  const double t = std::chrono::duration<double>(now - start_).count();
  if (t <= 0) return;
  const double rate = step / t;
  const double eta = rate > 0 ? (total_ - step) / rate : 0.0;
  std::printf("\rstep %lld/%lld (%3.0f%%)  %.0f steps/s  %.3g contact-steps/s  ETA %.0f s   ",
              static_cast<long long>(step), static_cast<long long>(total_), total_ > 0 ? 100.0 * step / total_ : 100.0,
              rate, contact_steps / t, eta);
  std::fflush(stdout);
  printed_ = true;
}

void ProgressLine::finish() {
  if (enabled_ && printed_) {
    std::printf("\n");
    std::fflush(stdout);
  }
}

}  // namespace driver
}  // namespace epac
