#pragma once
// The elliptical plane indenter of MDR space (Part I, Sections 5.5 and 6): full height A, full width
// B, pressed into a bed of springs of stiffness E_eff per unit length. Everything the force law
// needs from the ellipse: the force at a depth (30), the gap profile g_1D (44) and the contact
// half-width at a depth. Elastic regime: A = 4R, B = 2R (31); fully plastic: (28).
#include <epac/core/kokkos_compat.hpp>
#include <epac/core/lane_math.hpp>
#include <epac/core/simd_lanes.hpp>

namespace epac {

// The series of the bracket below: sum_{k>=1} (-1)^(k+1) 2^(2k) theta^(2k+1) / (2k+1)!, through
// k = 7: truncation below 1e-17 relative for theta < 0.25.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_ellipse_bracket_series(T th) {
  const T t2 = th * th;
  T s = T(16384.0 / 1307674368000.0);      // k = 7
  s = T(-4096.0 / 6227020800.0) + t2 * s;  // k = 6
  s = T(1024.0 / 39916800.0) + t2 * s;     // k = 5
  s = T(-256.0 / 362880.0) + t2 * s;       // k = 4
  s = T(64.0 / 5040.0) + t2 * s;           // k = 3
  s = T(-16.0 / 120.0) + t2 * s;           // k = 2
  s = T(4.0 / 6.0) + t2 * s;               // k = 1
  return s * t2 * th;
}

// theta - sin(theta) cos(theta), the bracket of (30) written with theta = acos(1 - 2 x),
// x = depth / A: then (1 - 2x) = cos(theta) and sqrt(4x - 4x^2) = sin(theta). For small theta the
// two terms cancel (error ~ eps/theta^2), so the series is used there (it is ~ (2/3) theta^3).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_ellipse_bracket(T th) {
  if (th < T(0.25)) return mdr_ellipse_bracket_series(th);
  return th - math::sin(th) * math::cos(th);
}

// The bracket of (30) as a function of x = depth / A in [0, 1], without sin/cos: with
// theta = 2 asin(sqrt(x)), sin(theta) cos(theta) = 2 sqrt(x (1 - x)) (1 - 2x) exactly
// (sin(theta/2) = sqrt(x), cos(theta/2) = sqrt(1 - x)). At the equator x = 1/2 (every plastic
// loading step, d = A/2 exactly) it is pi/2, returned without the asin.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_ellipse_bracket_of_depth(T x) {
  if (x == T(0.5)) return T(0.5) * constants<T>::pi;
  // x in [0, 1] (callers clamp): sqrt arguments >= 0
  const T sx = math::sqrt(x);
  const T th = T(2) * math::asin(sx);
  if (th < T(0.25)) return mdr_ellipse_bracket(th);  // series: the difference below cancels
  return th - T(2) * (T(1) - T(2) * x) * sx * math::sqrt_nonneg(T(1) - x);
}

// mdr_ellipse_bracket_of_depth without branches, for lanes (detail/mdr_side_lane.hpp): every
// branch computed and selected, theta by lane_two_asin_sqrt (core/lane_math.hpp) instead of libm's
// asin, so it agrees with the scalar form to a few ulp, not bit for bit (in scalar code libm's asin
// is the faster: docs/performance.md). Domain: x in [0, 1]; outside, the roots see x clamped.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_ellipse_bracket_of_depth_lane(T x) {
  const T xc = lane_min(lane_max(x, T(0)), T(1));
  const T sx = math::sqrt(xc);
  const T s1x = math::sqrt(T(1) - xc);  // xc <= 1
  const T th = lane_two_asin_sqrt(xc, sx, s1x);
  const T direct = th - T(2) * (T(1) - T(2) * xc) * sx * s1x;
  return lane_select(xc == T(0.5), T(0.5) * constants<T>::pi,
                     lane_select(th < T(0.25), mdr_ellipse_bracket_series(th), direct));
}

// MDR (30): force of the ellipse pressed to depth d into the springs.
//   F = E A B / 4 [acos(1 - 2d/A) - (1 - 2d/A) sqrt(4d/A - 4d^2/A^2)]
// Domain: 0 <= d <= A. d <= 0 gives 0 (no contact); d > A is clamped to A (the whole ellipse is
// submerged; unreachable in the plastic regime, where d <= A/2). theta = 2 asin(sqrt(d/A)) equals
// the acos of (30) without its loss of precision near d = 0.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_ellipse_force(T E, T A, T B, T d) {
  if (!(d > T(0)) || !(A > T(0))) return T(0);
  const T x = math::min(d / A, T(1));
  return E * A * B * T(0.25) * mdr_ellipse_bracket_of_depth(x);
}

// MDR (44): g_1D(a) = A/2 - (A/B) sqrt(B^2/4 - a^2), the ellipse's gap at half-width a. Written
// as (A/2) u^2 / (1 + sqrt(1 - u^2)), u = 2a/B, which does not cancel for small a. Domain:
// 0 <= a <= B/2; u is clamped to [0, 1] (a = B/2 gives the equator depth A/2).
template <class T>
KOKKOS_INLINE_FUNCTION T mdr_ellipse_gap(T A, T B, T a) {
  const T u = math::clamp(T(2) * a / B, T(0), T(1));
  const T u2 = u * u;
  return T(0.5) * A * u2 / (T(1) + math::sqrt_nonneg(T(1) - u2));
}

// d g_1D / da = (A/B) a / sqrt(B^2/4 - a^2). Diverges at a = B/2; the root solves that use it
// work inside [a_c, a_old] and treat an infinite slope as a bisection step (bracketed_newton).
template <class T>
KOKKOS_INLINE_FUNCTION T mdr_ellipse_gap_slope(T A, T B, T a) {
  const T q = T(0.25) * B * B - a * a;
  return q > T(0) ? A / B * a / math::sqrt(q) : T(0);  // 0 at/after the equator: Newton falls back
}

// Half-width of the ellipse's contact at depth d with no tension: the a with g_1D(a) = d,
// a = (B/A) sqrt(d (A - d)). Domain: 0 <= d <= A/2 (beyond the equator the width is B/2).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_ellipse_contact_radius(T A, T B, T d) {
  if (!(d > T(0))) return T(0);
  const T half = T(0.5) * A;
  if (d >= half) return T(0.5) * B;  // at/after the equator (plastic loading: d = A/2 exactly)
  const T dd = d;
  return B / A * math::sqrt_nonneg(dd * (A - dd));
}

}  // namespace epac
