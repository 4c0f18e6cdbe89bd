// EPAC_ARCH=auto (cmake/EpacArchFlags.cmake) compiles this together with cpu_guard.cpp under the
// candidate -march and runs it: the guard exits 1 before main where this CPU, or the OS's saved
// register state, lacks an extension those flags let the compiler use (a VM may report AVX-512
// and not enable it); main then runs a vectorisable loop, so a missing instruction the guard's
// list does not name shows as a crash.
#include <cstdio>

int main(int argc, char**) {
  double x[64], s = 0;
  for (int i = 0; i < 64; ++i) x[i] = argc * 0.5 + i;
  for (int i = 0; i < 64; ++i) s += x[i] * x[i] + 1.0 / x[i];
  std::printf("epac-arch-probe: ok %g\n", s);
  return s > 0 ? 0 : 1;
}
