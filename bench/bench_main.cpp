// Google Benchmark main that owns the Kokkos lifetime. Threads: OMP_NUM_THREADS (or
// --kokkos-threads / --kokkos-num-threads, which Kokkos strips before Google Benchmark parses).
#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

int main(int argc, char** argv) {
  Kokkos::ScopeGuard guard(argc, argv);
  benchmark::AddCustomContext("kokkos_backend", Kokkos::DefaultExecutionSpace::name());
  benchmark::AddCustomContext("kokkos_threads", std::to_string(Kokkos::DefaultExecutionSpace().concurrency()));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
