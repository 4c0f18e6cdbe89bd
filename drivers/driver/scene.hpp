#pragma once
// A scene (host side, double precision): what a scene file describes, after parsing and
// validation. Nothing here touches Kokkos; run_scene.hpp turns a Scene into device state.
// The file format is documented in drivers/README.md.
#include <epac/params/material.hpp>
#include <epac/params/validation.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace epac {
namespace driver {

using Vec3d = std::array<double, 3>;

// Every error in a scene file: names the key (with its table), the value and the valid range.
class SceneError : public ParameterError {
 public:
  using ParameterError::ParameterError;
};

// One piece of a piecewise-constant velocity (prescribed displacement of a wall or a driven
// particle).
struct MotionSegment {
  double duration = 0;  // [s]
  Vec3d velocity{0, 0, 0};
};

// Displacement over [t0, t1] of segments run in order from t = 0 (still after the last one).
Vec3d segments_displacement(const std::vector<MotionSegment>& segments, double t0, double t1);

struct ParticleSpec {
  Vec3d position{0, 0, 0};
  Vec3d velocity{0, 0, 0};
  Vec3d angular_velocity{0, 0, 0};
  double radius = 0;
  int material = 0;
  bool driven = false;  // velocity prescribed (not integrated): a sphere under prescribed displacement
  // Driven particles only: piecewise-constant velocity (then `velocity` is not given); still
  // after the last segment. Empty: the constant `velocity`.
  std::vector<MotionSegment> motion;
  std::string origin;  // "particles.list[3]" or "particles.fill": for messages
};

struct WallSpec {
  std::string name;       // optional; "wall<k>" if absent
  Vec3d point{0, 0, 0};   // a point on the plane
  Vec3d normal{0, 0, 1};  // unit normal into the domain (normalised on input)
  int material = 0;
  // Either a constant velocity forever (segments empty), or the segments in order; after the
  // last segment the wall stands still.
  Vec3d velocity{0, 0, 0};
  std::vector<MotionSegment> segments;

  // Displacement of the wall between t0 and t1 (t1 >= t0): the exact integral of the velocity.
  Vec3d displacement(double t0, double t1) const;
};

struct FillSpec {
  bool enabled = false;
  Vec3d box_min{0, 0, 0}, box_max{0, 0, 0};
  std::int64_t count = 0;
  double radius_min = 0, radius_max = 0;
  int material = 0;
  std::uint64_t seed = 1;
  Vec3d velocity{0, 0, 0};
};

// fcc lattice fill ([particles.lattice]): 4 atoms per cubic cell of edge a at (0,0,0),
// (.5,.5,0), (.5,0,.5), (0,.5,.5) a, cells looped z, y, x then the basis (LAMMPS create_atoms
// order); radii uniform in [radius_min, radius_max] and a uniform jitter in [-jitter, jitter]
// per coordinate, drawn in that order per atom from one seeded stream.
struct LatticeSpec {
  bool enabled = false;
  double a = 0;  // cubic cell edge [m]
  std::array<std::int64_t, 3> cells{0, 0, 0};
  Vec3d origin{0, 0, 0};  // corner of cell (0,0,0) [m]
  double radius_min = 0, radius_max = 0;
  int material = 0;
  std::uint64_t seed = 1;
  double jitter = 0;  // [m]
  Vec3d velocity{0, 0, 0};
  std::int64_t count() const { return 4 * cells[0] * cells[1] * cells[2]; }
};

// The simulation box ([box]): periodic axes wrap (minimum image, cell list across the faces);
// an affine deformation ([box.deform], LAMMPS `fix deform ... scale ... remap x`) scales the
// periodic edges about the box centre, linearly in the step number up to `deform_steps`.
struct BoxSpec {
  bool enabled = false;
  Vec3d lo{0, 0, 0}, hi{0, 0, 0};  // [m]
  std::array<bool, 3> periodic{false, false, false};
  bool deform = false;
  Vec3d scale{1, 1, 1};  // final edge / initial edge (1 on axes not deformed)
  std::int64_t deform_steps = 0;

  bool any_periodic() const { return periodic[0] || periodic[1] || periodic[2]; }
  double edge0(int d) const { return hi[d] - lo[d]; }
  double centre(int d) const { return 0.5 * (lo[d] + hi[d]); }
  // Edge along d after `step` steps: linear from edge0 (step 0) to scale x edge0 (step >=
  // deform_steps), then held.
  double edge(int d, std::int64_t step) const {
    if (!deform || deform_steps <= 0) return edge0(d);
    const double f = step >= deform_steps ? 1.0 : static_cast<double>(step) / static_cast<double>(deform_steps);
    return edge0(d) * (1.0 + (scale[d] - 1.0) * f);
  }
  // Smallest edge the run reaches along d.
  double min_edge(int d) const { return deform ? edge0(d) * std::min(1.0, scale[d]) : edge0(d); }
};

struct ModelSpec {
  std::string name = "hertz_mindlin";
  std::map<std::string, double> params;  // model-specific keys (model_registry.cpp lists them)
  bool effects_overridden = false;
  unsigned derived_effects = 0;    // from the materials (docs/design.md section 5)
  unsigned effects = 0;            // the active set: derived (masked by the model) or the override
  std::vector<std::string> notes;  // e.g. effects the model ignores
};

struct RunSpec {
  double dt = 0;
  std::int64_t steps = 0;
  std::int64_t output_interval = 0;  // 0: steps / 100 (at least 1)
  double skin = -1;                  // < 0: 0.2 x the smallest radius (see finish_scene)
  bool contact_output = false;       // contacts.csv at every output step
  bool particle_output = false;      // particles.csv at every output step
  // [run] spatial_sort: when the particle arrays are reordered into cell order (at a rebuild).
  // auto: at the first build and then at the first rebuild `sort_interval` steps after the last
  // sort, when the scene has at least kAutoSortMinParticles particles (drivers/README.md: the
  // measurement behind the rule); always: at every rebuild; never.
  enum class Sort { never, always, automatic };
  Sort spatial_sort = Sort::automatic;
  std::int64_t sort_interval = 1000;     // steps between sorts in auto mode (LAMMPS atom_modify sort's default)
  bool deterministic = false;            // the kernels' deterministic mode: same bits on any thread count
  std::string snapshot_format = "none";  // "vtp": ParaView/OVITO snapshots at every output step
  // "from_overlaps": contacts overlapping at step 0 get the history of a quasi-static load to
  // their overlap (compute/history_from_overlaps.hpp); "zero": fresh history.
  std::string initial_history = "from_overlaps";
};

struct Scene {
  std::string source;  // file name or "<string>"
  std::string description;
  std::vector<Material> materials;
  std::map<std::string, int> material_index;
  ModelSpec model;
  std::vector<ParticleSpec> particles;  // the explicit list, then the fill
  FillSpec fill;
  LatticeSpec lattice;
  BoxSpec box;
  bool allow_overlap = false;
  // [particles] order = "shuffled": the particles (list, fill, lattice) in a seeded random order,
  // the memory order a long mixing flow ends in (benchmarks of the spatial sort).
  bool shuffle = false;
  std::uint64_t order_seed = 1;
  std::vector<WallSpec> walls;
  Vec3d gravity{0, 0, 0};
  RunSpec run;

  double min_radius() const;
  double max_radius() const;
  bool any_driven() const;
};

// Parses and validates a scene. Throws SceneError (a ParameterError) with a message naming the
// key, its table, the value and the valid range; nothing else happens before it returns.
Scene parse_scene_file(const std::string& path);
Scene parse_scene_string(const std::string& text, const std::string& source = "<string>");

// Smallest Rayleigh time over the particles, pi R sqrt(rho/G) / (0.1631 nu + 0.8766): the
// usual bound for an explicit DEM time step with Hertz contacts (dt ~ 0.1-0.3 of it).
double rayleigh_time(const Scene& s);

// Particle mass (sphere of density rho) and moment of inertia (2/5) m R^2.
inline double sphere_mass(double density, double radius) {
  return density * 4.0 / 3.0 * 3.14159265358979323846 * radius * radius * radius;
}

}  // namespace driver
}  // namespace epac
