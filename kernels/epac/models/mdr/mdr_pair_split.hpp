#pragma once
// Particle pairs in MDR: a rigid flat at the contact plane splits the pair's apparent overlap
// delta into two sides, each a particle-flat contact with its own history (the authors'
// implementation; mdr-reference-notes.md "Particle pairs"). Side 0 is the particle with the smaller
// global id (ContactGeometry::i_is_first), so a side keeps its history across list rebuilds.
//
// - At the largest total overlap dmax the flat is the radical plane of the two spheres: side s gets
//   its cap height h_s = dmax (2 R_o - dmax) / (2 (R_s + R_o - dmax)) (R_o: the other radius), so
//   h_0 + h_1 = dmax and the smaller sphere takes the larger cap;
// - a side's height is capped at 0.75 of its radius, the remainder going to the other side;
// - below dmax each side moves linearly from h_s to its residual overlap delta_p,s, both reaching
//   them when delta = delta_p,0 + delta_p,1:
//   delta_s = h_s + (delta_p,s - h_s) (delta - dmax) / ((delta_p,0 + delta_p,1) - dmax).
#include <epac/core/kokkos_compat.hpp>

namespace epac {

template <class T>
KOKKOS_INLINE_FUNCTION constexpr T mdr_cap_height_limit() { return T(0.75); }

// Height of sphere R_self's cap cut by the radical plane of two spheres at overlap d:
// d (2 R_other - d) / (2 (R_self + R_other - d)). Domain: the centre distance R_self + R_other - d
// must be positive; it is kept at or above 1e-6 (R_self + R_other) (coincident centres).
// Valid for d <= 0 too (a small negative height: the spheres are apart).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_radical_cap_height(T d, T R_self, T R_other) {
  const T dist = math::max(R_self + R_other - d, T(1e-6) * (R_self + R_other));
  return d * (T(2) * R_other - d) / (T(2) * dist);
}

// Side 0's height at dmax with the 0.75 R cap (side 1 takes dmax minus this).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_side0_height(T dmax, T R0, T R1) {
  const T h0 = mdr_radical_cap_height(dmax, R0, R1);
  const T lim = mdr_cap_height_limit<T>();
  if (h0 > lim * R0) return lim * R0;
  if (dmax - h0 > lim * R1) return dmax - lim * R1;
  return h0;
}

template <class T>
struct MdrSideOverlaps {
  T d0, d1;
};

// Splits the pair's apparent overlap delta. dmax: largest total overlap so far (>= delta after the
// caller's update); dp0, dp1: the sides' residual overlaps (0 while elastic).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION MdrSideOverlaps<T> mdr_split_overlap(T delta, T dmax, T R0, T R1, T dp0, T dp1) {
  if (!(dmax > T(0))) {
    // never pressed together: the radical plane at the current (non-positive) overlap
    const T h0 = mdr_radical_cap_height(delta, R0, R1);
    return {h0, delta - h0};
  }
  const T h0 = mdr_side0_height(dmax, R0, R1);
  const T h1 = dmax - h0;
  if (delta >= dmax) return {h0, h1};
  // Denominator (dp0 + dp1) - dmax < 0 while the sides recover elastically (delta_p < delta_max
  // per side); kept at or below -1e-6 dmax if the residuals reach dmax (no elastic recovery).
  const T den = math::min(dp0 + dp1 - dmax, T(-1e-6) * dmax);
  const T t = (delta - dmax) / den;  // 0 at dmax, 1 at the summed residuals
  return {h0 + (dp0 - h0) * t, h1 + (dp1 - h1) * t};
}

}  // namespace epac
