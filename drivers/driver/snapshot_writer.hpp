#pragma once
// Particle snapshots for ParaView and OVITO ([run] snapshot_format = "vtp"): one VTK XML PolyData
// file per output step (snapshots/particles_<step>.vtp: one vertex per particle, ASCII) and a
// ParaView collection (particles.pvd) that lists them with their times, rewritten after each
// snapshot so an interrupted run still opens. Each file is written under NAME.partial and
// renamed when whole (outputs.hpp).
//
// Why .vtp + .pvd: ParaView opens a .pvd as a time series with named point arrays (Glyph or
// Point Gaussian by "radius" draws the spheres); OVITO 3's reader of ParaView VTP particle files
// takes the same files (File > Load File on a .vtp series or the .pvd). A LAMMPS dump would
// serve OVITO only. ASCII keeps the files readable and the test parser tiny; the
// cost is size (about 200 bytes per particle per snapshot).
#include <cstdint>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace epac {
namespace driver {

// One snapshot: per-particle arrays in particle order (host copies). Vectors are xyz-interleaved
// (3 n values). `extras`: model fields (name, n values), e.g. MDR's tracked volume.
struct ParticleSnapshot {
  std::int64_t step = 0;
  double time = 0;
  std::vector<double> x, v, omega, force;  // 3 n each; force: contact force (no gravity)
  std::vector<double> radius, radius0;     // n each
  std::vector<std::int64_t> id;            // global ids
  std::vector<int> material;
  std::vector<std::pair<std::string, std::vector<double>>> extras;
};

class SnapshotWriter {
 public:
  // Writes into `out_dir` (snapshots/ is created). Throws std::runtime_error when it cannot.
  explicit SnapshotWriter(const std::string& out_dir);
  void write(const ParticleSnapshot& s);
  const std::string& pvd_path() const { return pvd_path_; }

 private:
  std::string dir_, pvd_path_;
  std::vector<std::pair<double, std::string>> series_;  // (time, file relative to the .pvd)
};

// The .vtp text of one snapshot (exposed for the tests).
std::string vtp_text(const ParticleSnapshot& s);

}  // namespace driver
}  // namespace epac
