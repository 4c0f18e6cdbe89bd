// epac-run SCENE.toml [--out DIR] [--threads N] [--steps N] [--precision double|float] [--quiet]
//          [--phase-times]
// epac-run --version
// Parses and validates the scene before Kokkos starts, so bad input is refused before anything
// runs or is written. Exit status: 0 success, 1 runtime failure, 2 invalid input.
#include "driver/model_registry.hpp"
#include "driver/scene.hpp"

#include <CLI/CLI.hpp>
#include <Kokkos_Core.hpp>
#include <epac/core/build_info.hpp>
#include <epac/core/kokkos_compat.hpp>

#include <cstdio>
#include <exception>
#include <memory>
#include <unistd.h>


int main(int argc, char** argv) {
  CLI::App app{"epac-run: run a DEM scene with the epac contact kernels"};
  std::string scene_path;
  epac::driver::RunOptions opt;
  int threads = 0;
  app.add_option("scene", scene_path, "scene file (TOML; see drivers/README.md)")->required()->check(CLI::ExistingFile);
  app.add_option("--out", opt.out_dir, "output folder (default ./epac-out)");
  app.add_option("--threads", threads, "threads (default: OMP_NUM_THREADS / Kokkos default)")
      ->check(CLI::Range(1, 4096));
  app.add_option("--steps", opt.steps, "number of steps (overrides [run] steps)")->check(CLI::Range(int64_t(0), int64_t(1000000000000LL)));
  app.add_option("--precision", opt.precision, "scalar type: double (default) or float")
      ->check(CLI::IsMember({"double", "float"}));
  app.add_flag("--quiet", opt.quiet, "no informational output and no progress line");
  app.add_flag("--deterministic", opt.deterministic,
               "deterministic mode: the same bits for any thread count (as [run] deterministic = true)");
  app.add_flag("--phase-times", opt.phase_times,
               "seconds per loop phase (detection, remap, force, growth, integration, output) in summary.json");
  app.add_option("--time-after", opt.time_after,
                 "also time the steps after N alone (summary.json \"timed\"; e.g. a hold phase)")
      ->check(CLI::Range(int64_t(0), int64_t(1000000000000LL)));
  // --version: epac's version, Kokkos's version and its enabled backends, e.g.
  // "epac 0.1.0 (Kokkos 3.4.1: Serial OpenMP)"; exits 0 without a scene.
  app.set_version_flag("--version", epac::build_info());
  CLI11_PARSE(app, argc, argv);
  opt.progress = isatty(fileno(stdout)) != 0;

  epac::driver::Scene scene;
  try {
    scene = epac::driver::parse_scene_file(scene_path);
  } catch (const epac::ParameterError& e) {
    std::fprintf(stderr, "epac-run: invalid scene: %s\n", e.what());
    return 2;
  }
  auto kokkos = epac::start_kokkos(threads);
  try {
    epac::driver::run(scene, opt);
  } catch (const epac::ParameterError& e) {
    std::fprintf(stderr, "epac-run: invalid input: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "epac-run: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
