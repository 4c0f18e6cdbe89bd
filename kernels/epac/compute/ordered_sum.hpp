#pragma once
// A sum over 0..n-1 whose bits do not depend on the thread count: fixed chunks of 256 terms, each
// summed in index order by one thread, then the chunk sums in order on the host. For diagnostics
// (energies, wall forces) that must be reproducible across thread counts; Kokkos::parallel_reduce
// joins per-thread partial sums, whose split depends on the thread count.
#include <epac/core/kokkos_compat.hpp>

#include <string>

namespace epac {

// term(i) -> double, a device callable. One small allocation per call (meant for output samples).
template <class Exec, class Term>
double ordered_sum(const char* label, int n, const Term& term) {
  constexpr int chunk = 256;
  if (n <= 0) return 0.0;
  const int nchunks = (n + chunk - 1) / chunk;
  Kokkos::View<double*, typename Exec::memory_space> part(std::string(label), nchunks);
  Kokkos::parallel_for(
      label, Kokkos::RangePolicy<Exec>(0, nchunks), KOKKOS_LAMBDA(int c) {
        const int end = (c + 1) * chunk < n ? (c + 1) * chunk : n;
        double s = 0.0;
        for (int i = c * chunk; i < end; ++i) s += term(i);
        part(c) = s;
      });
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), part);
  double sum = 0.0;
  for (int c = 0; c < nchunks; ++c) sum += h(c);
  return sum;
}

}  // namespace epac
