// An executable of epac's own with nothing but main: cpu_guard.cmake runs it on this CPU (main
// runs) and, where the build uses AVX-512, under valgrind, whose CPU lacks it (the guard stops it).
#include <cstdio>

int main() {
  std::puts("cpu_guard_main: main ran");
  return 0;
}
