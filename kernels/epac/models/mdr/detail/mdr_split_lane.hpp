#pragma once
// The geometric pair split (detail/mdr_pair_split.hpp, MdrPairSplit::geometric) without branches,
// for contacts in lanes (Mdr::contact_lane): its common path in a held or unloading packing, a
// pair below its largest overlap dmax and above its summed residuals (x >= 0 in
// mdr_split_overlap). Loading (delta >= dmax), a pair never pressed (dmax <= 0) and the
// separated range below the residuals are flagged rare for the one-contact code.
// The values are mdr_split_overlap's expressions in its order, with its ternaries as selects, so
// the two forms give the same bits where the compiler contracts them alike.
#include <epac/core/simd_lanes.hpp>
#include <epac/models/mdr/detail/mdr_pair_split.hpp>

namespace epac {

// mdr_radical_cap_height as selects. Division by the centre distance, kept >= 1e-6 (R0 + R1).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_radical_cap_height_lane(T d, T R_self, T R_other) {
  const T dist = lane_max(R_self + R_other - d, T(1e-6) * (R_self + R_other));
  return d * (T(2) * R_other - d) / (T(2) * dist);
}

// mdr_side0_height as selects: the capped radical height, clamped to [0, max(d, 0)].
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_side0_height_lane(T d, T R0, T R1) {
  const T h0 = mdr_radical_cap_height_lane(d, R0, R1);
  const T lim = mdr_cap_height_limit<T>();
  const T h = lane_select(h0 > lim * R0, lim * R0, lane_select(d - h0 > lim * R1, d - lim * R1, h0));
  const T hi = lane_max(d, T(0));
  return lane_select(h < T(0), T(0), lane_select(hi < h, hi, h));  // math::clamp(h, 0, hi)
}

template <class T>
struct MdrSplitLane {
  T d0, d1;
  T rare;  // 1: not on the common path (d0, d1 then finite placeholders)
};

// mdr_split_overlap(delta, dmax, R0, R1, dp0, dp1, false) where 0 < dmax, delta < dmax and
// delta >= the clamped residuals' sum; rare elsewhere. X = dmax - S > 0 there (the division);
// on rare lanes it is replaced by 1.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION MdrSplitLane<T> mdr_split_overlap_lane(T delta, T dmax, T R0, T R1, T dp0, T dp1) {
  const T h0 = mdr_side0_height_lane(dmax, R0, R1);
  const T h1 = dmax - h0;
  const T e0 = lane_select(dp0 < T(0), T(0), lane_select(h0 < dp0, h0, dp0));  // math::clamp(dp0, 0, h0)
  const T e1 = lane_select(dp1 < T(0), T(0), lane_select(h1 < dp1, h1, dp1));
  const T S = e0 + e1;
  const T x = delta - S;
  const bool common = (dmax > T(0)) & !(delta >= dmax) & (x >= T(0));
  const T X = lane_select(common, dmax - S, T(1));
  const T E0 = h0 - e0, E1 = h1 - e1;
  T d0 = e0 + mdr_side0_height_lane(x, R0, R1) + (x / X) * (E0 - mdr_side0_height_lane(X, R0, R1));
  const T lo = e0 + lane_max(T(0), x - E1), hi = e0 + lane_min(x, E0);
  d0 = lane_select(d0 < lo, lo, lane_select(hi < d0, hi, d0));  // math::clamp(d0, lo, hi)
  MdrSplitLane<T> out;
  out.d0 = d0;
  out.d1 = delta - d0;
  out.rare = lane_select(common, T(0), T(1));
  return out;
}

}  // namespace epac
