// epac-run SCENE.toml [--out DIR] [--overwrite] [--threads N] [--steps N] [--precision double|float]
//          [--quiet] [--phase-times] [--time-after N]
// epac-run --version
// Parses and validates the scene before Kokkos starts, so bad input is refused before anything
// runs or is written. Exit status: 0 completed, 1 run-time failure (e.g. an output cannot be
// written), 2 invalid input (scene, option, an --out folder with another run's outputs),
// 3 diverged (summary.json status "diverged"), 128 + signal when SIGINT (130) or SIGTERM (143)
// stopped the run (summary.json status "interrupted").
#include "driver/model_registry.hpp"
#include "driver/scene.hpp"
#include "driver/stop_signal.hpp"

#include <CLI/CLI.hpp>
#include <Kokkos_Core.hpp>
#include <epac/core/build_info.hpp>
#include <epac/core/kokkos_compat.hpp>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <sched.h>
#include <thread>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace {

// The threads this process can use: the CPUs of its affinity mask, else the hardware count.
// With OMP_PROC_BIND set, libgomp binds the initial thread to its first place when it loads
// (before main), so the mask then holds one place only; omp_get_num_procs() keeps the count
// libgomp found before binding. The larger of the two is the process's.
int available_threads() {
  int n = 0;
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) n = CPU_COUNT(&set);
#ifdef _OPENMP
  n = std::max(n, omp_get_num_procs());
#endif
  if (n > 0) return n;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? static_cast<int>(hw) : 1;
}

// --threads (or OMP_NUM_THREADS when --threads is absent) clamped to what the machine has:
// more threads than CPUs only oversubscribe, and very large counts crash inside Kokkos'
// thread-data setup. Returns the count for start_kokkos (0: Kokkos's default).
int bounded_threads(int requested) {
  const char* source = "--threads";
  if (requested <= 0) {
    const char* env = std::getenv("OMP_NUM_THREADS");
    if (!env) return 0;
    char* end = nullptr;
    const long n = std::strtol(env, &end, 10);  // "8" or the first entry of "8,4"
    if (end == env || n <= 0) return 0;
    requested = n > INT_MAX ? INT_MAX : static_cast<int>(n);
    source = "OMP_NUM_THREADS";
  }
  const int avail = available_threads();
  if (requested <= avail) return requested;
  std::fprintf(stderr,
               "epac-run: warning: %s = %d is more than the %d CPUs this process can use (valid range "
               "[1, %d]); running with %d threads\n",
               source, requested, avail, avail, avail);
  return avail;
}

// OpenMP thread binding where the user chose none. libgomp reads OMP_PROC_BIND and OMP_PLACES
// once, when it loads (before main), and without them runs unbound; Kokkos then warns at every
// start that binding is unset. epac-run keeps the unbound default and says so: it sets
// OMP_PROC_BIND=false for Kokkos's check (which matches what libgomp already does). Binding is
// not the default because processes that each bind start their threads on the same first CPUs
// (two 1-thread runs side by side, as ctest -j2 starts them, would share one core). On a machine
// the run has to itself, OMP_PROC_BIND=spread OMP_PLACES=threads (docs/performance.md) is the
// user's choice, and is kept as given.
void default_openmp_binding() {
  if (!std::getenv("OMP_PROC_BIND") && !std::getenv("OMP_PLACES")) setenv("OMP_PROC_BIND", "false", 1);
}

}  // namespace

int main(int argc, char** argv) {
  default_openmp_binding();
  CLI::App app{"epac-run: run a DEM scene with the epac contact kernels"};
  std::string scene_path;
  epac::driver::RunOptions opt;
  int threads = 0;
  app.add_option("scene", scene_path, "scene file (TOML; see drivers/README.md)")->required()->check(CLI::ExistingFile);
  app.add_option("--out", opt.out_dir, "output folder (default ./epac-out); refused if it holds another run's outputs");
  app.add_flag("--overwrite", opt.overwrite,
               "remove the epac-run outputs of an earlier run in --out first (other files stay)");
  app.add_option("--threads", threads,
                 "threads (default: OMP_NUM_THREADS / Kokkos default); above the CPUs available: "
                 "clamped with a warning")
      ->check(CLI::Range(1, INT_MAX));
  app.add_option("--steps", opt.steps, "number of steps (overrides [run] steps)")
      ->check(CLI::Range(int64_t(0), int64_t(1000000000000LL)));
  app.add_option("--precision", opt.precision, "scalar type: double (default) or float")
      ->check(CLI::IsMember({"double", "float"}));
  app.add_flag("--quiet", opt.quiet, "no informational output and no progress line");
  app.add_flag("--deterministic", opt.deterministic,
               "deterministic mode: the same bits for any thread count (as [run] deterministic = true)");
  app.add_flag("--phase-times", opt.phase_times,
               "seconds per loop phase (detection, remap, force, growth, integration, output) in summary.json "
               "(with --time-after, the window's own in \"timed\")");
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
  auto kokkos = epac::start_kokkos(bounded_threads(threads));
  epac::driver::install_stop_handlers();  // SIGINT/SIGTERM: stop after the current step
  try {
    const epac::driver::RunSummary sum = epac::driver::run(scene, opt);
    if (sum.status == "interrupted") {
      std::fprintf(stderr, "epac-run: interrupted (%s); whole outputs up to step %lld in %s\n",
                   sum.status_reason.c_str(), static_cast<long long>(sum.steps_completed), opt.out_dir.c_str());
      return 128 + sum.stop_signal;
    }
  } catch (const epac::ParameterError& e) {
    std::fprintf(stderr, "epac-run: invalid input: %s\n", e.what());
    return 2;
  } catch (const epac::driver::DivergedError& e) {
    std::fprintf(stderr, "epac-run: error: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "epac-run: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
