#pragma once
// Particle pairs in MDR: a rigid flat at the contact plane splits the pair's apparent overlap
// delta into two sides, each a particle-flat contact with its own history (docs/models.md, "MDR
// conventions", row "particle pairs"). Side 0 is the particle with the smaller global id
// (ContactGeometry::i_is_first), so a side keeps its history across list rebuilds.
//
// This file is the geometric split (the authors' rule, repaired as below). It is the first
// guess of the balanced split (mdr_pair_balance.hpp), which places the flat where the
// sides' scaled forces balance: that makes the pair passive; the geometric split alone, with the
// mean force, returned more work than it took on ~1% of random plastic cycles. For two equal
// spheres with equal histories the guess is already the balance.
//
// - At and above the largest total overlap dmax (loading) the flat is the radical plane of the two
//   spheres: side s gets its cap height h_s = d (2 R_o - d) / (2 (R_s + R_o - d)) (R_o: the other
//   radius), so h_0 + h_1 = d and the smaller sphere takes the larger cap; a side's height is
//   capped at 0.75 of its radius, the remainder going to the other side (as the authors' code).
// - Below dmax (where epac departs from the authors' code). The authors move each side linearly
//   from h_s to its residual delta_p,s, both reached at delta = delta_p,0 + delta_p,1:
//   t = (delta - dmax) / ((delta_p,0 + delta_p,1) - dmax). That has two defects:
//   (a) when the residuals sum to dmax or more (no elastic recovery left, or a side whose residual
//       exceeds its present height after its radius grew) the denominator is 0 or positive; floored
//       it made t ~ 1e6 and threw one side 1e7 R deep (Inf/NaN with radius growth);
//   (b) on an elastic pair of unequal spheres the unloading path (linear in delta) is not the
//       loading path (the radical plane, nonlinear in delta), so the pair force is two-valued and a
//       closed cycle returned +0.12% of its work.
//   epac instead: with e_s = delta_p,s clamped to [0, h_s] (a side never targets a residual above
//   where it stands at dmax), S = e_0 + e_1 <= dmax, the recoverable parts E_s = h_s - e_s and
//   x = delta - S in [0, X], X = dmax - S = E_0 + E_1:
//     d_0 = e_0 + h_0(x) + (x / X) (E_0 - h_0(X))      [h_0(x): the capped radical height]
//   clamped so that both sides stay within [e_s, h_s] (never beyond a residual, never above dmax's
//   height, so no side reloads while the pair unloads); d_1 = delta - d_0. x / X is in [0, 1]
//   (no extrapolation). An elastic pair (e_s = 0) gets d_0 = h_0(delta), the loading path itself,
//   so its force is single-valued in delta and a closed cycle is conservative.
//   Below the summed residuals (x < 0, also the whole range below dmax when X = 0) both sides move
//   below their residuals, separated, by the uncapped radical height of x: |d_s - e_s| <= |x|.
// The split is continuous in delta and d_0 + d_1 = delta everywhere (the flat stays between the
// spheres).
// authors_unloading (MdrPairSplit::geometric_authors): the authors' path itself below dmax,
//   d_0 = h_0 + (delta_p,0 - h_0) (delta - dmax) / ((delta_p,0 + delta_p,1) - dmax)
// (LAMMPS gran_sub_mod_normal.cpp, GranSubModNormalMDR::calculate_forces, and its mean surface
// displacement in fix_granular_mdr.cpp), for like-with-like comparisons; where its denominator is
// not negative (defect (a)) epac's path above is taken instead. For equal spheres with equal
// residuals both paths are the same line.
#include <epac/core/kokkos_compat.hpp>

namespace epac {

template <class T>
KOKKOS_INLINE_FUNCTION constexpr T mdr_cap_height_limit() {
  return T(0.75);
}

// Height of sphere R_self's cap cut by the radical plane of two spheres at overlap d:
// d (2 R_other - d) / (2 (R_self + R_other - d)). Domain: the centre distance R_self + R_other - d
// must be positive; it is kept at or above 1e-6 (R_self + R_other) (coincident centres).
// Valid for d <= 0 too (a small negative height in (d, 0): the spheres are apart).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_radical_cap_height(T d, T R_self, T R_other) {
  const T dist = math::max(R_self + R_other - d, T(1e-6) * (R_self + R_other));
  return d * (T(2) * R_other - d) / (T(2) * dist);
}

// Side 0's height at total overlap d >= 0 with the 0.75 R cap (side 1 takes d minus this); in
// [0, d].
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_side0_height(T dmax, T R0, T R1) {
  const T h0 = mdr_radical_cap_height(dmax, R0, R1);
  const T lim = mdr_cap_height_limit<T>();
  T h = h0;
  if (h0 > lim * R0)
    h = lim * R0;
  else if (dmax - h0 > lim * R1)
    h = dmax - lim * R1;
  return math::clamp(h, T(0), math::max(dmax, T(0)));  // beyond both caps (d > 1.5 R): stay in [0, d]
}

template <class T>
struct MdrSideOverlaps {
  T d0, d1;
};

// Splits the pair's apparent overlap delta. dmax: largest total overlap so far (>= delta after the
// caller's update); dp0, dp1: the sides' residual overlaps (0 while elastic); authors_unloading:
// the authors' path below dmax (above).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION MdrSideOverlaps<T> mdr_split_overlap(T delta, T dmax, T R0, T R1, T dp0, T dp1,
                                                                 bool authors_unloading = false) {
  if (!(dmax > T(0))) {
    // never pressed together: the radical plane at the current (non-positive) overlap
    const T h0 = mdr_radical_cap_height(delta, R0, R1);
    return {h0, delta - h0};
  }
  const T h0 = mdr_side0_height(dmax, R0, R1);
  const T h1 = dmax - h0;
  if (delta >= dmax) return {h0, h1};  // loading (the caller keeps dmax >= delta)
  if (authors_unloading) {
    const T den = (dp0 + dp1) - dmax;
    if (den < T(0)) {
      const T d0 = h0 + (dp0 - h0) * (delta - dmax) / den;
      return {d0, delta - d0};
    }
  }
  const T e0 = math::clamp(dp0, T(0), h0), e1 = math::clamp(dp1, T(0), h1);
  const T S = e0 + e1;
  const T x = delta - S;
  T d0;
  if (x >= T(0)) {
    // S <= x + S = delta < dmax, so X > 0 and x / X in [0, 1)
    const T X = dmax - S;
    const T E0 = h0 - e0, E1 = h1 - e1;
    d0 = e0 + mdr_side0_height(x, R0, R1) + (x / X) * (E0 - mdr_side0_height(X, R0, R1));
    d0 = math::clamp(d0, e0 + math::max(T(0), x - E1), e0 + math::min(x, E0));
  } else {
    d0 = e0 + mdr_radical_cap_height(x, R0, R1);  // in (e0 + x, e0): separated, bounded
  }
  return {d0, delta - d0};
}

}  // namespace epac
