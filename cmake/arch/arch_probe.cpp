// EPAC_ARCH=auto (cmake/EpacArchFlags.cmake) compiles this with the candidate -march and runs it:
// it exits 0 only where this CPU, and the OS's saved register state, support every x86 extension
// those flags let the compiler use (the list of cpu_guard.cpp; a VM may report AVX-512 and not
// enable it). A vectorisable loop runs too, so a missing instruction also shows as a crash.
#include <cstdio>

#if defined(__x86_64__) || defined(__i386__)
#define EPAC_REQUIRE(feature)                              \
  if (!__builtin_cpu_supports(feature)) {                  \
    std::printf("epac-arch-probe: missing %s\n", feature); \
    missing = 1;                                           \
  }
#endif

int main(int argc, char**) {
  int missing = 0;
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
#ifdef __SSE4_2__
  EPAC_REQUIRE("sse4.2")
#endif
#ifdef __POPCNT__
  EPAC_REQUIRE("popcnt")
#endif
#ifdef __AVX__
  EPAC_REQUIRE("avx")
#endif
#ifdef __AVX2__
  EPAC_REQUIRE("avx2")
#endif
#ifdef __FMA__
  EPAC_REQUIRE("fma")
#endif
#ifdef __BMI__
  EPAC_REQUIRE("bmi")
#endif
#ifdef __BMI2__
  EPAC_REQUIRE("bmi2")
#endif
#ifdef __AVX512F__
  EPAC_REQUIRE("avx512f")
#endif
#ifdef __AVX512VL__
  EPAC_REQUIRE("avx512vl")
#endif
#ifdef __AVX512BW__
  EPAC_REQUIRE("avx512bw")
#endif
#ifdef __AVX512DQ__
  EPAC_REQUIRE("avx512dq")
#endif
#endif
  if (missing) return 1;
  double x[64], s = 0;
  for (int i = 0; i < 64; ++i) x[i] = argc * 0.5 + i;
  for (int i = 0; i < 64; ++i) s += x[i] * x[i] + 1.0 / x[i];
  std::printf("epac-arch-probe: ok %g\n", s);
  return s > 0 ? 0 : 1;
}
