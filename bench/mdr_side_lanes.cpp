// MDR's side law on the hold's common path (a yielded side below its delta_max on its stored shape,
// 98.4% of the side evaluations of a compressed packing's hold), per side: the one-side law
// mdr_side_force against its lane form mdr_side_force_lane (detail/mdr_side_lane.hpp) in blocks of
// the host's contact lanes (core/simd_lanes.hpp). The sides' state is read from one array per
// history field, as the contact history keeps it. Ratios are what to read (docs/performance.md).
#include <benchmark/benchmark.h>
#include <epac/core/simd_lanes.hpp>
#include <epac/models/mdr/detail/mdr_side_lane.hpp>
#include <epac/models/mdr/mdr_parameters.hpp>

#include <random>

using namespace epac;

namespace {

using Exec = Kokkos::DefaultHostExecutionSpace;
using Dev = Kokkos::Device<Exec, Exec::memory_space>;

template <class T>
struct HoldSides {
  MdrSideConstants<T> c;
  Kokkos::View<T*, Dev> delta, R, delta_o_max, yielded, c_A, delta_p, shape_R, shape_delta_max, shape_A, shape_a_max,
      shape_ratio, out;
  int n = 0;

  KOKKOS_FORCEINLINE_FUNCTION MdrSideState<T> state(int k) const {
    MdrSideState<T> s;
    s.delta_o_max = delta_o_max(k);
    s.yielded = yielded(k);
    s.c_A = c_A(k);
    s.delta_p = delta_p(k);
    s.shape_R = shape_R(k);
    s.shape_delta_max = shape_delta_max(k);
    s.shape_A = shape_A(k);
    s.shape_a_max = shape_a_max(k);
    s.shape_ratio = shape_ratio(k);
    return s;
  }
};

// n sides of the fcc benchmark's material (E 1e9 Pa, nu 0.3, Y 5 MPa), radii 0.94-0.99 mm, each
// loaded to delta_max in [0.10, 0.15] R and then a little below it, as in the hold.
template <class T>
HoldSides<T> make_hold_sides(int n) {
  Material m;
  m.youngs_modulus = 1e9;
  m.poisson_ratio = 0.3;
  m.density = 1000;
  m.yield_stress = 5e6;
  HoldSides<T> h;
  h.n = n;
  h.c = mdr_side_constants<T>(m, MdrYieldOnset::hertz_40);
  Kokkos::View<T*, Dev>* fields[] = {&h.delta,   &h.R,           &h.delta_o_max, &h.yielded,
                                     &h.c_A,     &h.delta_p,     &h.shape_R,     &h.shape_delta_max,
                                     &h.shape_A, &h.shape_a_max, &h.shape_ratio, &h.out};
  for (auto* f : fields) *f = Kokkos::View<T*, Dev>("hold_side", n);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < n; ++k) {
    const T R = T(1e-3 * (0.94 + 0.05 * u(rng)));
    const T dmax = T(double(R) * (0.10 + 0.05 * u(rng)));
    MdrSideState<T> s;
    for (int i = 1; i <= 30; ++i)
      mdr_side_force<true, false>(h.c, T(0), T(1), T(dmax * i / 30), R, T(0), s, T(1), false);
    h.delta(k) = T(double(dmax) * (1.0 - 1e-3 * u(rng)));
    h.R(k) = R;
    h.delta_o_max(k) = s.delta_o_max;
    h.yielded(k) = s.yielded;
    h.c_A(k) = s.c_A;
    h.delta_p(k) = s.delta_p;
    h.shape_R(k) = s.shape_R;
    h.shape_delta_max(k) = s.shape_delta_max;
    h.shape_A(k) = s.shape_A;
    h.shape_a_max(k) = s.shape_a_max;
    h.shape_ratio(k) = s.shape_ratio;
  }
  return h;
}

template <class T>
void BM_MdrSideLaw_OneSide(benchmark::State& state) {
  const HoldSides<T> h = make_hold_sides<T>(int(state.range(0)));
  for (auto _ : state) {
    Kokkos::parallel_for(
        "bench::mdr_side_one", Kokkos::RangePolicy<Exec>(0, h.n), KOKKOS_LAMBDA(int k) {
          MdrSideState<T> s = h.state(k);
          const MdrSideResult<T> r =
              mdr_side_force<true, false>(h.c, T(0), T(1), h.delta(k), h.R(k), T(0), s, T(1), false);
          h.out(k) = r.F + r.a + r.area;
        });
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * h.n);
  state.counters["ns_per_side"] =
      benchmark::Counter(double(h.n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <class T>
void BM_MdrSideLaw_Lanes(benchmark::State& state) {
  constexpr int W = contact_lanes<Exec, T>::value > 1 ? contact_lanes<Exec, T>::value : 1;
  const HoldSides<T> h = make_hold_sides<T>(int(state.range(0)) / W * W);
  for (auto _ : state) {
    Kokkos::parallel_for(
        "bench::mdr_side_lanes", Kokkos::RangePolicy<Exec>(0, h.n / W), KOKKOS_LAMBDA(int b) {
          T L_F[W];
          for (int l = 0; l < W; ++l) {
            const int k = b * W + l;
            const MdrSideLane<T> r = mdr_side_force_lane(h.c, h.delta(k), h.R(k), T(0), h.state(k));
            L_F[l] = r.F + r.a + r.area + r.rare;
          }
          for (int l = 0; l < W; ++l) h.out(b * W + l) = L_F[l];
        });
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * h.n);
  state.counters["lanes"] = W;
  state.counters["ns_per_side"] =
      benchmark::Counter(double(h.n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK_TEMPLATE(BM_MdrSideLaw_OneSide, double)->Arg(1 << 17);
BENCHMARK_TEMPLATE(BM_MdrSideLaw_Lanes, double)->Arg(1 << 17);
BENCHMARK_TEMPLATE(BM_MdrSideLaw_OneSide, float)->Arg(1 << 17);
BENCHMARK_TEMPLATE(BM_MdrSideLaw_Lanes, float)->Arg(1 << 17);
