// Linked into each of epac's own executables when they are built with an -march
// (cmake/EpacArchFlags.cmake). Before the program's other code runs it checks that this CPU, and
// the OS's saved register state, support the x86 extensions the build's flags let the compiler
// use; where one is missing it exits with a message that says what to do, instead of dying later
// on an illegal instruction (a native build copied to another machine: a cluster's login node to
// its compute nodes). The function itself is compiled for the x86-64 baseline, so it runs anywhere.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cstdio>
#include <cstdlib>

namespace {
// 101: the first priority open to programs, so before any static initialiser of epac's own code
__attribute__((constructor(101), target("arch=x86-64"))) void epac_cpu_guard() {
  __builtin_cpu_init();
  const char* missing[11];
  int n = 0;
  // __builtin_cpu_supports takes a literal: one line per extension the compiler may have used
#define EPAC_GUARD_NEED(feature) \
  if (!__builtin_cpu_supports(feature)) missing[n++] = feature;
#ifdef __SSE4_2__
  EPAC_GUARD_NEED("sse4.2")
#endif
#ifdef __POPCNT__
  EPAC_GUARD_NEED("popcnt")
#endif
#ifdef __AVX__
  EPAC_GUARD_NEED("avx")
#endif
#ifdef __AVX2__
  EPAC_GUARD_NEED("avx2")
#endif
#ifdef __FMA__
  EPAC_GUARD_NEED("fma")
#endif
#ifdef __BMI__
  EPAC_GUARD_NEED("bmi")
#endif
#ifdef __BMI2__
  EPAC_GUARD_NEED("bmi2")
#endif
#ifdef __AVX512F__
  EPAC_GUARD_NEED("avx512f")
#endif
#ifdef __AVX512VL__
  EPAC_GUARD_NEED("avx512vl")
#endif
#ifdef __AVX512BW__
  EPAC_GUARD_NEED("avx512bw")
#endif
#ifdef __AVX512DQ__
  EPAC_GUARD_NEED("avx512dq")
#endif
#undef EPAC_GUARD_NEED
  if (n == 0) return;
  std::fprintf(stderr, "epac: this program was built for a CPU with extensions this one lacks:");
  for (int i = 0; i < n; ++i) std::fprintf(stderr, " %s", missing[i]);
  std::fprintf(stderr,
               "\nepac: rebuild it on this machine (the README's commands build for the CPU they run on), "
               "or configure with -DEPAC_ARCH=portable for executables that move between machines.\n");
  std::_Exit(1);
}
}  // namespace
#endif
