// STREAM-like triad a(i) = b(i) + s c(i) on the Kokkos default execution space, and the bytes per
// contact-step of each contact kernel, so docs/performance.md can say what fraction of the machine's
// bandwidth each law reaches (bytes per contact-step x contact-steps per second / triad GB/s), and
// the peak multiply-add rate of this build (bench/roofline/roofline.py puts them together).
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
#include <cmath>
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

// Peak arithmetic of this build, measured: each thread runs N independent multiply-add chains
// acc = acc m + a (2 flops each) in registers. N is a template so the compiler can unroll and
// vectorise as far as the build's flags let it (SSE2 without -march; FMA and wider vectors with
// it); the best N over a sweep is the machine's peak for this build. Scalar code (one contact per
// thread) reaches at most peak / lanes of the vector width the compiler used.
template <class T, int N>
double multiply_add_gflops(int repeats) {
  using exec = Kokkos::DefaultExecutionSpace;
  const int threads = exec().concurrency();
  Kokkos::View<T*> sink("sink", threads);
  const long iters = 1L << 22;
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    Kokkos::fence();
    const auto t0 = std::chrono::steady_clock::now();
    Kokkos::parallel_for(
        "epac::peak_multiply_add", Kokkos::RangePolicy<exec>(0, threads), KOKKOS_LAMBDA(int t) {
          T acc[N];
          for (int k = 0; k < N; ++k) acc[k] = T(1) + T(k) * T(1e-3) + T(t);
          const T m = T(0.999), a = T(1e-3);  // acc -> 1: stays normal, never overflows
          for (long it = 0; it < iters; ++it)
            for (int k = 0; k < N; ++k) acc[k] = acc[k] * m + a;
          T s = 0;
          for (int k = 0; k < N; ++k) s += acc[k];
          sink(t) = s;
        });
    Kokkos::fence();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return 2.0 * N * double(iters) * threads / best / 1e9;
}

template <class T>
double peak_gflops(int repeats) {
  return std::max({multiply_add_gflops<T, 8>(repeats), multiply_add_gflops<T, 16>(repeats),
                   multiply_add_gflops<T, 24>(repeats), multiply_add_gflops<T, 32>(repeats),
                   multiply_add_gflops<T, 48>(repeats), multiply_add_gflops<T, 64>(repeats),
                   multiply_add_gflops<T, 96>(repeats), multiply_add_gflops<T, 128>(repeats)});
}

// Core clock in GHz, measured on the calling thread: a chain of dependent register-to-register
// integer adds retires one add per cycle on every x86-64 core, so adds per second is the clock the
// code ran at (turbo included), which the roofline needs for instructions per cycle where perf has
// no cycle counter. Not `add $1`: Intel's recent cores (this project's Xeon with AMX, 2026-12-06)
// fold adds of a small immediate at rename, and a chain of them read 16-19 "GHz" on a 4.1 GHz core.
// 0 where not measured (other architectures).
double clock_ghz() {
#if defined(__x86_64__) && !defined(__CUDA_ARCH__) && !defined(__HIP_DEVICE_COMPILE__)
  double best = 0;
  for (int r = 0; r < 3; ++r) {
    unsigned long x = 0;
    const unsigned long one = 1;
    const long n = 1L << 26;
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = 0; i < n; ++i)
      asm volatile(
          "add %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\t"
          "add %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\tadd %1, %0"
          : "+r"(x)
          : "r"(one));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (x == 8UL * n) best = std::max(best, 8.0 * double(n) / s / 1e9);
  }
  return best;
#else
  return 0;
#endif
}

// Latency in ns of one division and of one square root on the calling thread, from dependent
// chains (each result feeds the next): what a contact kernel's chain of them costs at the least.
// The sqrt chain x = sqrt(x + c) includes an add, whose own chain x = x + c is timed and taken off.
// Without -ffast-math the compiler keeps every operation (none of them may be reassociated); the
// chains are functions of their own so that x stays in a register.
template <class T>
struct OpLatencies {
  double add_ns, div_ns, sqrt_ns;
};
template <class T>
[[gnu::noinline]] T add_chain(T x, T c, long n) {
  for (long i = 0; i < n; ++i) x = x + c;
  return x;
}
template <class T>
[[gnu::noinline]] T div_chain(T x, T c, long n) {
  for (long i = 0; i < n; ++i) x = c / x;
  return x;
}
template <class T>
[[gnu::noinline]] T sqrt_chain(T x, T c, long n) {
  for (long i = 0; i < n; ++i) x = std::sqrt(x + c);
  return x;
}
template <class T, class Chain>
double chain_ns(Chain chain) {
  const long n = 1L << 24;
  volatile T seed = T(1.5);  // unknown to the compiler: no chain is folded
  double best = 1e30;
  for (int r = 0; r < 3; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    volatile T sink = chain(T(seed), T(seed), n);
    (void)sink;
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best / double(n) * 1e9;
}
template <class T>
OpLatencies<T> op_latencies() {
  OpLatencies<T> l;
  l.add_ns = chain_ns<T>(add_chain<T>);
  l.div_ns = chain_ns<T>(div_chain<T>);
  l.sqrt_ns = chain_ns<T>(sqrt_chain<T>) - l.add_ns;
  return l;
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
  const double peak_d = peak_gflops<double>(std::max(1, repeats / 2));
  const double peak_f = peak_gflops<float>(std::max(1, repeats / 2));
  std::printf("peak multiply-add GFLOP/s of this build (all threads): double %.1f, float %.1f\n", peak_d, peak_f);
  const double ghz = clock_ghz();
  std::printf("core clock (dependent adds): %.2f GHz\n", ghz);
  const auto ld = op_latencies<double>();
  const auto lf = op_latencies<float>();
  std::printf(
      "latency ns (dependent chains, one thread): double add %.2f div %.2f sqrt %.2f; float add %.2f div %.2f "
      "sqrt %.2f\n",
      ld.add_ns, ld.div_ns, ld.sqrt_ns, lf.add_ns, lf.div_ns, lf.sqrt_ns);
  out +=
      "},\n  \"peak_GFLOPs\": {\"double\": " + std::to_string(peak_d) + ", \"float\": " + std::to_string(peak_f) + "}";
  out += ",\n  \"clock_GHz\": " + std::to_string(ghz);
  out += ",\n  \"latency_ns\": {\"double\": {\"add\": " + std::to_string(ld.add_ns) +
         ", \"div\": " + std::to_string(ld.div_ns) + ", \"sqrt\": " + std::to_string(ld.sqrt_ns) +
         "}, \"float\": {\"add\": " + std::to_string(lf.add_ns) + ", \"div\": " + std::to_string(lf.div_ns) +
         ", \"sqrt\": " + std::to_string(lf.sqrt_ns) + "}}";
  out += ",\n  \"bytes_per_contact_step\": {";
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
