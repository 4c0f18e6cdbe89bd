#pragma once
// epac-sticking-velocity's library: the critical sticking velocity of one particle hitting a
// wall (Nan Sec. 4, Table 6), found by running the driver (epac_driver: scene parser, model
// registry, run loop) at impact speeds chosen by bisection, each run classified as stick or
// rebound from its timeseries.csv.
//
// Classification of one run (force_<wall> sampled at every step, contact law + damping):
//   rebound:  the force was non-zero at some step (contact formed) and is exactly 0 at the last
//             step: the model reports a detached contact as inactive (force 0), and without gravity
//             a detached particle only moves away (re-contact needs a positive overlap);
//   stick:    after the first compressive sample the force went tensile and then compressive
//             again, i.e. the particle separated, turned back while still attached and hit the
//             wall again (damping only removes energy, so it can never leave afterwards);
//   neither:  the run was too short to tell (an error naming [run] steps).
#include "driver/scene.hpp"

#include <epac/params/nan2022/nan2022_sticking_velocity.hpp>

#include <functional>
#include <string>
#include <vector>

namespace epac {
namespace sticking {

// The one-particle-on-one-wall scene, checked: exactly one explicit particle (no fill), one wall
// (its normal is the impact direction), no gravity, double precision (the gap is nanometres).
struct ImpactScene {
  driver::Scene scene;
  double radius = 0, mass = 0;
  std::string wall_name;
};

// Throws ParameterError naming what is wrong with the scene.
ImpactScene make_impact_scene(const driver::Scene& s);

enum class Outcome { stick, rebound };

struct ImpactRun {
  double V = 0;  // impact speed [m/s]
  Outcome outcome = Outcome::stick;
  double rebound_speed = 0;  // [m/s], sqrt(2 KE / m) at the last step (0 when stuck)
  double max_force = 0;      // largest compressive force [N]
  double min_force = 0;      // most tensile force [N] (< 0)
  std::int64_t steps = 0;
  double wall_time_s = 0;
};

// Reads a driver timeseries.csv (one row per step) and classifies the impact.
ImpactRun classify_timeseries(const std::string& csv_path, const ImpactScene& s, double V);

// One driver run at impact speed V (velocity -V n_wall), outputs in out_dir, classified.
ImpactRun simulate_impact(const ImpactScene& s, double V, const std::string& out_dir);

struct StickingSearch {
  double lo = 0, hi = 0;        // final bracket: lo sticks, hi rebounds
  double V_ys = 0;              // (lo + hi) / 2
  std::vector<ImpactRun> runs;  // in the order run
};

// Bisection on [lo, hi] until hi - lo <= rel_tol * hi. Throws ParameterError if lo does not
// stick or hi does not rebound. on_run (optional) sees every run as it finishes.
StickingSearch find_sticking_velocity(const ImpactScene& s, double lo, double hi, double rel_tol,
                                      const std::string& out_dir,
                                      const std::function<void(const ImpactRun&)>& on_run = {});

// Nan (73)-(79) for the scene's particle-wall pair (model nan2022 only; its [model] options).
struct AnalyticSticking {
  bool available = false;
  Nan2022StickingVelocities v;
  Nan2022PairReport report;
};
AnalyticSticking nan2022_analytic(const ImpactScene& s);

}  // namespace sticking
}  // namespace epac
