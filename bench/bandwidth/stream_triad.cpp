// STREAM-like triad a(i) = b(i) + s c(i) on the Kokkos default execution space, and the bytes per
// contact-step of each contact kernel, so docs/performance.md can say what fraction of the machine's
// bandwidth each law reaches (bytes per contact-step x contact-steps per second / triad GB/s).
//
//   epac-stream-triad [--json FILE] [--repeats N]
// Threads: OMP_NUM_THREADS / --kokkos-threads. Sizes: arrays of 32 KiB (L1), 256 KiB (L2),
// 2 MiB and 64 MiB (DRAM) each; the triad moves 3 arrays (24 B per double element; a write
// allocate would add 8 B, not counted, as in STREAM).
//
// Bytes per contact-step: what one contact reads and writes if nothing is reused from cache (an
// upper bound; contacts sorted by first particle reuse particle i's data): the list entry, the two
// particles' fields the kernel loads, the history row read and written, and the force/torque
// sums (read-modify-write of both particles). See contact_kernel_bytes below.
#include <Kokkos_Core.hpp>
#include <epac/core/kokkos_compat.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/nan2022/nan2022.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

double triad_gbs(std::size_t n, int repeats) {
  using exec = Kokkos::DefaultExecutionSpace;
  Kokkos::View<double*> a("a", n), b("b", n), c("c", n);
  Kokkos::deep_copy(b, 1.0);
  Kokkos::deep_copy(c, 2.0);
  const double s = 3.0;
  // enough sweeps per timing that small arrays are timed over >= ~2 ms
  const int sweeps = static_cast<int>(std::max<std::size_t>(1, (std::size_t(1) << 24) / n));
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    Kokkos::fence();
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < sweeps; ++k)
      Kokkos::parallel_for(
          "epac::triad", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(std::size_t i) { a(i) = b(i) + s * c(i); });
    Kokkos::fence();
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / sweeps;
    best = std::min(best, dt);
  }
  return 3.0 * sizeof(double) * double(n) / best / 1e9;
}

struct KernelBytes {
  const char* name;
  int history_fields;     // per contact
  int particle_loads;     // values loaded per particle (x 3 in double, v 3, omega 3, radius, mass, [gid], ...)
  int sums_per_particle;  // scalars accumulated per particle (force 3 + torque 3 [+ MDR 3])
};

// Bytes of one contact-step with scalar size s: list entry (2 ints), history read + write,
// both particles' loads (the 3 position components are double for any s: mixed precision,
// state/particles.hpp), and a read + write of each accumulated scalar on both particles.
std::size_t contact_kernel_bytes(const KernelBytes& k, std::size_t s) {
  const std::size_t loads = 3 * sizeof(double) + (k.particle_loads - 3) * s;
  return 2 * sizeof(int) + 2 * k.history_fields * s + 2 * loads + 2 * 2 * k.sums_per_particle * s;
}

template <class T>
std::vector<KernelBytes> kernels() {
  using namespace epac;
  constexpr unsigned FD = kFriction | kDamping;
  // particle loads: x, v, omega (9), radius, mass (2); MDR adds gid (8 bytes ~ 8/sizeof(T)
  // scalars, counted as 1 for double, 2 for float) and radius0; Nan/JKR read the same as HM.
  const int gid = sizeof(T) == 8 ? 1 : 2;
  return {
      {"hertz_mindlin", HertzMindlin<T, Effects<FD>>::history_size, 11, 6},
      {"jkr", Jkr<T, Effects<FD | kAdhesion>>::history_size, 11, 6},
      {"nan2022", Nan2022<T, Effects<FD | kAdhesion | kPlasticity>>::history_size, 11, 6},
      {"mdr_plasticity", Mdr<T, Effects<FD | kPlasticity>>::history_size, 11 + gid, 6},
      {"mdr_plasticity_growth", Mdr<T, Effects<FD | kPlasticity | kRadiusGrowth>>::history_size, 13 + gid, 9},
      {"mdr_all_effects", Mdr<T, Effects<FD | kPlasticity | kRadiusGrowth | kAdhesion>>::history_size, 13 + gid, 9},
  };
}

}  // namespace

int main(int argc, char** argv) {
  std::string json_path;
  int repeats = 5;
  for (int a = 1; a < argc; ++a) {
    if (!std::strcmp(argv[a], "--json") && a + 1 < argc)
      json_path = argv[++a];
    else if (!std::strcmp(argv[a], "--repeats") && a + 1 < argc)
      repeats = std::atoi(argv[++a]);
  }
  Kokkos::ScopeGuard guard(argc, argv);
  const int threads = Kokkos::DefaultExecutionSpace().concurrency();
  const std::size_t sizes[] = {std::size_t(32) << 10, std::size_t(256) << 10, std::size_t(2) << 20,
                               std::size_t(64) << 20};
  const char* labels[] = {"32KiB", "256KiB", "2MiB", "64MiB"};
  std::string out = "{\n  \"backend\": \"" + std::string(Kokkos::DefaultExecutionSpace::name()) +
                    "\",\n  \"threads\": " + std::to_string(threads) + ",\n  \"triad_GBps\": {";
  std::printf("triad (%s, %d threads), GB/s per array size:\n", Kokkos::DefaultExecutionSpace::name(), threads);
  for (int k = 0; k < 4; ++k) {
    const double g = triad_gbs(sizes[k] / sizeof(double), repeats);
    std::printf("  %-7s %8.1f\n", labels[k], g);
    out += std::string(k ? ", " : "") + "\"" + labels[k] + "\": " + std::to_string(g);
  }
  out += "},\n  \"bytes_per_contact_step\": {";
  std::printf("bytes per contact-step (no cache reuse; double / float):\n");
  const auto kd = kernels<double>();
  const auto kf = kernels<float>();
  for (std::size_t k = 0; k < kd.size(); ++k) {
    const std::size_t bd = contact_kernel_bytes(kd[k], 8), bf = contact_kernel_bytes(kf[k], 4);
    std::printf("  %-22s %4zu / %4zu\n", kd[k].name, bd, bf);
    out += std::string(k ? ", " : "") + "\"" + kd[k].name + "\": {\"double\": " + std::to_string(bd) +
           ", \"float\": " + std::to_string(bf) + "}";
  }
  out += "}\n}\n";
  if (!json_path.empty()) {
    FILE* f = std::fopen(json_path.c_str(), "w");
    if (f) {
      std::fputs(out.c_str(), f);
      std::fclose(f);
    }
  }
  return 0;
}
