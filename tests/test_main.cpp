// Catch2 main that owns the Kokkos lifetime (ScopeGuard), so every test case can launch kernels.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <Kokkos_Core.hpp>

#include <cstdlib>

int main(int argc, char* argv[]) {
  // Kokkos 3.x prints an OMP_PROC_BIND advice to stdout when it is unset, which would end up in
  // ctest's test discovery (--list-test-names-only) as bogus test names. Unit tests want
  // OMP_PROC_BIND=false anyway (Kokkos's own advice).
  setenv("OMP_PROC_BIND", "false", /*overwrite=*/0);
  Kokkos::ScopeGuard guard(argc, argv);
  return Catch::Session().run(argc, argv);
}
