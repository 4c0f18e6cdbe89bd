#pragma once
// Contacts in lanes (compute/pair_lanes.hpp): how many contacts one work item of the pair kernel
// takes on an execution space, and the branch-free select its lanes use.
// Host backends: a block of 8 contacts per work item (16 in float with 512-bit vectors), whose
// middle loop the host compiler turns into SIMD instructions of the width the build allows (2
// doubles with SSE4.1, 4 with AVX2, 8 with AVX-512). No intrinsics and no `omp simd` (its lowering
// moves each lane's small vectors into strided arrays the vectoriser cannot store). GPUs: one
// lane, i.e. one contact per thread, the same source.
// g++ 12 vectorises the loop only where the target has 64-bit integer compares and blends (x86:
// SSE4.1 and later). On the x86-64 baseline (SSE2) the loop stays scalar and measured slower
// than the one-contact kernel (docs/performance.md, "Contacts in lanes"): there the width is 0
// and the pair kernel takes one contact per work item, as before.
#include <Kokkos_Core.hpp>

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace epac {

#if defined(__SSE4_1__)
inline constexpr int kContactLanesHost = 8;  // 8 measured best of 4 / 8 / 16 (AVX-512, double)
#else
inline constexpr int kContactLanesHost = 0;  // not vectorised here: the one-contact kernel
#endif

// Whether the host compiler vectorises the lanes with 512-bit vectors: AVX-512, unless the build
// tunes for an Intel core, where GCC prefers 256-bit vectors (X86_TUNE_AVX256_OPTIMAL; a build
// with -mprefer-vector-width=256 should define EPAC_LANES_256). The lanes' block of float and
// their index width follow it (docs/performance.md, "One 512-bit vector per block").
#if defined(__AVX512F__) && !defined(EPAC_LANES_256) &&                                                       \
    !(defined(__tune_skylake_avx512__) || defined(__tune_cascadelake__) || defined(__tune_cooperlake__) ||    \
      defined(__tune_cannonlake__) || defined(__tune_icelake_client__) || defined(__tune_icelake_server__) || \
      defined(__tune_tigerlake__) || defined(__tune_rocketlake__) || defined(__tune_sapphirerapids__) ||      \
      defined(__tune_graniterapids__) || defined(__tune_graniterapids_d__) || defined(__tune_emeraldrapids__))
inline constexpr bool kHostLanes512 = true;
#else
inline constexpr bool kHostLanes512 = false;
#endif

// Float lanes with 512-bit vectors: 16, one vector of float per block (with 8, float's block is
// half a vector: 0.84-0.89 of the time with 16 on AMD Zen 5; with 256-bit vectors 16 lanes
// measured 1.08 of 8).
inline constexpr int kContactLanesHostFloat = kHostLanes512 ? 2 * kContactLanesHost : kContactLanesHost;

template <class ExecutionSpace, class T = double>
struct contact_lanes
    : std::integral_constant<int, std::is_same<typename ExecutionSpace::memory_space, Kokkos::HostSpace>::value
                                      ? (sizeof(T) == 4 ? kContactLanesHostFloat : kContactLanesHost)
                                      : 1> {};

// Particles in lanes (the driver's integration, driver/integrator.hpp): the same width on host
// backends, one particle per work item where contacts take no lanes and on GPUs.
template <class ExecutionSpace>
struct particle_lanes
    : std::integral_constant<int,
                             (contact_lanes<ExecutionSpace>::value > 1 ? contact_lanes<ExecutionSpace>::value : 1)> {};

// A lane count fixed at compile time, usable where a run-time count is (a loop bound): a full
// block's loops then have a constant trip count and the host compiler emits vector loads and
// stores. Not std::integral_constant: its conversion to int is a host function to nvcc.
template <int N>
struct LaneCount {
  KOKKOS_FORCEINLINE_FUNCTION constexpr operator int() const { return N; }
};

// c ? a : b as bit operations: a ternary is a branch to the compiler's middle end, and jump
// threading then duplicates the code after it for each side, which leaves stores and divisions
// on one path only (the vectoriser gives up: "control flow in loop"). Both operands are
// evaluated; the result is exactly a or b.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T lane_select(bool c, T a, T b) {
  using U = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  static_assert(sizeof(T) == sizeof(U), "lane_select: a 4- or 8-byte type (float, double, int)");
  U ua, ub;
  memcpy(&ua, &a, sizeof(T));
  memcpy(&ub, &b, sizeof(T));
  const U mask = U(0) - U(c);
  const U r = (ua & mask) | (ub & ~mask);
  T out;
  memcpy(&out, &r, sizeof(T));
  return out;
}
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T lane_max(T a, T b) {
  return lane_select(a < b, b, a);  // math::max's result, as a select
}
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T lane_min(T a, T b) {
  return lane_select(b < a, b, a);  // math::min's result, as a select
}

// One lane's normal history for a law's lane form with history (compute/pair_lanes.hpp): the
// law reads and rewrites the N fields and sets `rare` where its common path does not hold (the
// kernel then takes the law's scalar normal() for that lane, from the stored row).
template <class T, int N>
struct LaneHistory {
  T v[N];
  bool rare;
};

// One lane's pair contact for a lane form that reads per-particle or per-contact state of its own
// (compute/pair_lanes.hpp, `contact_lane`): the particles (i before j in global-id order), the
// contact's index in its list, the overlap and the radii.
template <class T, class Index>
struct LaneContact {
  Index i, j, k;  // one index type: mixed widths split the host's vectors (compute/pair_lanes.hpp)
  T delta, R_i, R_j, R_eff;
};

// One lane of a block's lane arrays (a[field][lane]): field f of lane l is a[f][l]. A contact
// lane form reads and writes its history and its sums through it, so the lane loop keeps no copy
// (a loop over a copy's fields is an inner loop, which the vectoriser refuses).
template <class T, int W>
struct LaneColumn {
  T (*a)[W];
  int l;
  KOKKOS_FORCEINLINE_FUNCTION T& operator[](int f) const { return a[f][l]; }
};

}  // namespace epac
