#include "sticking_velocity/impact_search.hpp"

#include "driver/csv_columns.hpp"
#include "driver/model_registry.hpp"
#include "driver/models/nan2022_options.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

namespace epac {
namespace sticking {

namespace {

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string c;
  while (std::getline(ss, c, ',')) cells.push_back(c);
  return cells;
}

std::string fmt(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

}  // namespace

ImpactScene make_impact_scene(const driver::Scene& s) {
  const std::string where = s.source + ": ";
  if (s.particles.size() != 1 || s.fill.enabled)
    throw ParameterError(where + "needs exactly one particle in [[particles.list]] and no [particles.fill] (has " +
                         std::to_string(s.particles.size()) + ")");
  if (s.walls.size() != 1)
    throw ParameterError(where + "needs exactly one [[walls]] entry (has " + std::to_string(s.walls.size()) + ")");
  if (s.gravity[0] != 0 || s.gravity[1] != 0 || s.gravity[2] != 0)
    throw ParameterError(where + "gravity must be zero (a detached particle must not come back)");
  const auto& w = s.walls[0];
  if (!w.segments.empty() || w.velocity[0] != 0 || w.velocity[1] != 0 || w.velocity[2] != 0)
    throw ParameterError(where + "the wall must stand still");
  const auto& q = s.particles[0];
  if (q.driven) throw ParameterError(where + "the particle must not be driven");
  double gap = 0;
  for (int d = 0; d < 3; ++d) gap += (q.position[d] - w.point[d]) * w.normal[d];
  gap -= q.radius;
  if (!(gap > 0))
    throw ParameterError(where + "the particle must start clear of the wall: its gap = " + fmt(gap) +
                         " m (distance to the wall minus radius) must be > 0");
  ImpactScene r;
  r.scene = s;
  r.radius = q.radius;
  r.mass = driver::sphere_mass(s.materials[q.material].density, q.radius);
  r.wall_name = w.name;
  r.scene.run.output_interval = 1;  // the classification reads every step
  return r;
}

ImpactRun classify_timeseries(const std::string& csv_path, const ImpactScene& s, double V) {
  std::ifstream in(csv_path);
  if (!in) throw std::runtime_error("cannot read '" + csv_path + "'");
  std::string line;
  std::getline(in, line);
  const auto header = split_commas(line);
  int col_f = -1, col_ke = -1;
  for (int k = 0; k < static_cast<int>(header.size()); ++k) {
    const std::string name = driver::csv_column_name(header[k]);  // "force_top [N]" -> "force_top"
    if (name == "force_" + s.wall_name) col_f = k;
    if (name == "ke_translational") col_ke = k;
  }
  if (col_f < 0 || col_ke < 0)
    throw std::runtime_error(csv_path + ": no force_" + s.wall_name + " or ke_translational column");
  ImpactRun r;
  r.V = V;
  // phases of the force sequence: 0 before compression, 1 compressed, 2 tensile after it, 3 again compressed
  int phase = 0;
  bool touched = false;
  double f_last = 0, ke_last = 0;
  std::int64_t rows = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto c = split_commas(line);
    if (static_cast<int>(c.size()) <= std::max(col_f, col_ke)) throw std::runtime_error(csv_path + ": short row");
    const double f = std::stod(c[col_f]);
    ke_last = std::stod(c[col_ke]);
    f_last = f;
    ++rows;
    if (f != 0) touched = true;
    r.max_force = std::max(r.max_force, f);
    r.min_force = std::min(r.min_force, f);
    if (phase == 0 && f > 0)
      phase = 1;
    else if (phase == 1 && f < 0)
      phase = 2;
    else if (phase == 2 && f > 0)
      phase = 3;
  }
  r.steps = rows > 0 ? rows - 1 : 0;
  if (!touched)
    throw ParameterError(s.scene.source + ": at V = " + fmt(V) + " m/s the particle never reached the wall in " +
                         std::to_string(r.steps) + " steps: raise [run] steps or reduce the gap");
  if (f_last == 0.0) {
    r.outcome = Outcome::rebound;
    r.rebound_speed = std::sqrt(std::max(0.0, 2.0 * ke_last / s.mass));
    return r;
  }
  if (phase == 3) {
    r.outcome = Outcome::stick;
    return r;
  }
  throw ParameterError(s.scene.source + ": at V = " + fmt(V) + " m/s the impact was not over after " +
                       std::to_string(r.steps) +
                       " steps (still attached, not yet back in compression): raise [run] steps");
}

ImpactRun simulate_impact(const ImpactScene& s, double V, const std::string& out_dir) {
  require_positive("impact velocity V", V);
  driver::Scene sc = s.scene;
  auto& q = sc.particles[0];
  const auto& n = sc.walls[0].normal;
  for (int d = 0; d < 3; ++d) q.velocity[d] = -V * n[d];
  q.angular_velocity = {0, 0, 0};
  driver::RunOptions o;
  o.out_dir = out_dir;
  o.overwrite = true;  // each impact of the search replaces the previous one's outputs
  o.quiet = true;
  o.progress = false;
  o.precision = "double";
  const auto t0 = std::chrono::steady_clock::now();
  const driver::RunSummary sum = driver::run(sc, o);
  ImpactRun r = classify_timeseries(sum.timeseries_path, s, V);
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

StickingSearch find_sticking_velocity(const ImpactScene& s, double lo, double hi, double rel_tol,
                                      const std::string& out_dir, const std::function<void(const ImpactRun&)>& on_run) {
  require_positive("--lo", lo);
  require_range("--hi", hi, lo, Bound::open, std::numeric_limits<double>::infinity(), Bound::open);
  require_range("--tol", rel_tol, 1e-9, Bound::closed, 0.5, Bound::closed);
  StickingSearch r;
  auto run = [&](double V) {
    const ImpactRun x = simulate_impact(s, V, out_dir);
    r.runs.push_back(x);
    if (on_run) on_run(x);
    return x.outcome;
  };
  if (run(lo) != Outcome::stick) throw ParameterError("--lo = " + fmt(lo) + " m/s already rebounds: give a lower --lo");
  if (run(hi) != Outcome::rebound) throw ParameterError("--hi = " + fmt(hi) + " m/s still sticks: give a higher --hi");
  while (hi - lo > rel_tol * hi) {
    const double mid = 0.5 * (lo + hi);
    (run(mid) == Outcome::rebound ? hi : lo) = mid;
  }
  r.lo = lo;
  r.hi = hi;
  r.V_ys = 0.5 * (lo + hi);
  return r;
}

AnalyticSticking nan2022_analytic(const ImpactScene& s) {
  AnalyticSticking a;
  if (s.scene.model.name != "nan2022") return a;
  const auto& sc = s.scene;
  const Material& particle = sc.materials[sc.particles[0].material];
  const Material& wall = sc.materials[sc.walls[0].material];
  const Nan2022PairConstants<double> p = nan2022_pair_constants(particle, wall, driver::nan2022_options(sc));
  a.v = nan2022_sticking_velocities(p, s.radius, s.mass);  // wall: R* = R, m* = m
  a.report = nan2022_pair_report(p, s.radius);
  a.available = true;
  return a;
}

}  // namespace sticking
}  // namespace epac
