// epac-sticking-velocity SCENE.toml [--lo V] [--hi V] [--tol REL] [--out DIR] [--threads N] [--quiet]
// The critical sticking velocity of one particle hitting a wall (Nan Sec. 4): driver runs of the
// scene at impact speeds chosen by bisection, each classified as stick or rebound; prints V_ys
// next to the analytic Nan (78)-(79) value (model nan2022). Exit status: 0 success, 2 invalid
// scene or input (the message names the key or value), 1 other failures.
#include "driver/outputs.hpp"
#include "driver/scene.hpp"
#include "sticking_velocity/impact_search.hpp"

#include <CLI/CLI.hpp>
#include <Kokkos_Core.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <epac/core/kokkos_compat.hpp>

#include <exception>
#include <fstream>
#include <memory>

namespace {

const char* outcome_name(epac::sticking::Outcome o) {
  return o == epac::sticking::Outcome::stick ? "stick" : "rebound";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace epac::sticking;
  CLI::App app{
      "epac-sticking-velocity: critical sticking velocity of one particle on a wall by bisection on "
      "driver runs (Nan Sec. 4)"};
  std::string scene_path, out_dir = "epac-sticking-out";
  double lo = 0, hi = 0, tol = 1e-3;
  int threads = 1;
  bool quiet = false;
  app.add_option("scene", scene_path, "scene: one particle, one wall (drivers/sticking_velocity/README.md)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--lo", lo, "impact speed that sticks [m/s] (default: 0.5 x the analytic V_ys, model nan2022)");
  app.add_option("--hi", hi, "impact speed that rebounds [m/s] (default: 3 x the analytic V_ys, model nan2022)");
  app.add_option("--tol", tol, "stop when hi - lo <= tol x hi (default 1e-3)");
  app.add_option("--out", out_dir, "output folder (default ./epac-sticking-out)");
  app.add_option("--threads", threads, "Kokkos threads (default 1: one contact)")->check(CLI::Range(1, 4096));
  app.add_flag("--quiet", quiet, "print only the result line");
  CLI11_PARSE(app, argc, argv);

  ImpactScene s;
  AnalyticSticking a;
  try {
    s = make_impact_scene(epac::driver::parse_scene_file(scene_path));
    a = nan2022_analytic(s);
    if (!(lo > 0) || !(hi > 0)) {
      if (!a.available || !(a.v.V_ys > 0))
        throw epac::ParameterError("--lo and --hi are required: the scene's model " + s.scene.model.name +
                                   " has no analytic V_ys to start from");
      if (!(lo > 0)) lo = 0.5 * a.v.V_ys;
      if (!(hi > 0)) hi = 3.0 * a.v.V_ys;
    }
  } catch (const epac::ParameterError& e) {
    std::fprintf(stderr, "epac-sticking-velocity: invalid input: %s\n", e.what());
    return 2;
  }

  auto kokkos = epac::start_kokkos(threads);
  StickingSearch r;
  try {
    epac::driver::make_output_dir(out_dir);
    if (!quiet) {
      std::printf("epac-sticking-velocity: %s: R = %g m, m = %g kg, model %s, dt = %g s, %lld steps per run\n",
                  scene_path.c_str(), s.radius, s.mass, s.scene.model.name.c_str(), s.scene.run.dt,
                  static_cast<long long>(s.scene.run.steps));
      std::printf("bisection on [%g, %g] m/s to %g (relative)\n", lo, hi, tol);
      std::printf("   V [m/s]   outcome   rebound [m/s]   e = v_out/V   f_max [N]     f_min [N]     time [s]\n");
    }
    r = find_sticking_velocity(s, lo, hi, tol, out_dir + "/run", [&](const ImpactRun& x) {
      if (!quiet)
        std::printf("%10.6g   %-7s   %13.6g   %11.4g   %11.4g   %11.4g   %8.3f\n", x.V, outcome_name(x.outcome),
                    x.rebound_speed, x.rebound_speed / x.V, x.max_force, x.min_force, x.wall_time_s);
      std::fflush(stdout);
    });
  } catch (const epac::ParameterError& e) {
    std::fprintf(stderr, "epac-sticking-velocity: invalid input: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "epac-sticking-velocity: error: %s\n", e.what());
    return 1;
  }

  std::printf("V_ys (simulated) = %.6g m/s (bracket [%.6g, %.6g], %zu runs)", r.V_ys, r.lo, r.hi, r.runs.size());
  if (a.available)
    std::printf("; analytic Nan (78)-(79), no damping: V_ys = %.6g m/s, V_s = %.6g m/s (Nan (73))%s", a.v.V_ys, a.v.V_s,
                a.v.always_yields ? ", adhesion-induced yield (f_y < f_0)" : "");
  std::printf("\n");

  nlohmann::json j;
  j["scene"] = scene_path;
  j["model"] = s.scene.model.name;
  j["radius"] = s.radius;
  j["mass"] = s.mass;
  j["dt"] = s.scene.run.dt;
  j["steps_per_run"] = s.scene.run.steps;
  j["tol"] = tol;
  j["V_ys"] = r.V_ys;
  j["bracket"] = {r.lo, r.hi};
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& x : r.runs)
    runs.push_back({{"V", x.V},
                    {"outcome", outcome_name(x.outcome)},
                    {"rebound_speed", x.rebound_speed},
                    {"max_force", x.max_force},
                    {"min_force", x.min_force},
                    {"wall_time_s", x.wall_time_s}});
  j["runs"] = runs;
  if (a.available) {
    j["analytic"] = {{"V_s", a.v.V_s},
                     {"V_y0", a.v.V_y0},
                     {"V_y", a.v.V_y},
                     {"V_ys", a.v.V_ys},
                     {"always_yields", a.v.always_yields},
                     {"yields_before_sticking", a.v.yields_before_sticking},
                     {"cohesion_yield_number", a.report.cohesion_yield_number},
                     {"note", "Nan (73)-(79): no damping (e0 = 1)"}};
  }
  const std::string path = out_dir + "/sticking_velocity.json";
  std::ofstream f(path);
  f << j.dump(2) << "\n";
  if (!f) {
    std::fprintf(stderr, "epac-sticking-velocity: error: cannot write %s\n", path.c_str());
    return 1;
  }
  if (!quiet) std::printf("wrote %s (last run's timeseries in %s/run)\n", path.c_str(), out_dir.c_str());
  return 0;
}
