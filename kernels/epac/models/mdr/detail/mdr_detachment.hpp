#pragma once
// When an adhesive MDR contact detaches, from its state alone: the critical
// overlap below which no adhesive equilibrium exists, whatever path led there (a single step from
// deep contact to far apart included), so the release does not depend on how long the host's
// neighbour list keeps the pair.
//
// - One side, in MDR space: MDR (15) with xi = 1 (displacement control) is d h/da = 0 for
//   h(a) = g_1D(a) - Delta l(a) (g_1D of (44), Delta l of (11)); its root a_c is h's only minimum on
//   [0, B/2] (h falls from h(0) = 0, then rises). A side in tension holds only while d >= h(a) for
//   its stored a (edge springs within Delta l) or d = h(a) with a >= a_c (peeling, (48)), so it can
//   hold only for d >= d_c = h(a_c) <= 0. Below d_c the side law (mdr_adhesion.hpp) separates.
// - The same in the side's apparent overlap: elastic, d = delta; fully plastic, on the fixed
//   ellipse of delta_max, d = A/2 + (delta - delta_max)/r (MDR (35), mdr_side_force.hpp), so
//   delta_c,s = delta_p + r d_c (delta_p = delta_max - r A/2). Since r in (0, 1] and
//   d_c >= -Delta l(B/2) >= -Delta l(R): delta_c,s >= delta_p - sqrt(2 pi R gamma_s / E_eff), the
//   bound the driver's adhesive range uses (drivers/driver/models/mdr.cpp).
// - A pair: the two sides are in series across the flat at the contact plane, and the split
//   (mdr_pair_balance.hpp) gives them overlaps that sum to the pair's; the pair's critical overlap
//   is the sum of its sides' (equal elastic spheres: JKR's delta_c of the two spheres). Below it the
//   chain is broken whatever the split does with the individual sides. The balance usually lets go
//   earlier: when the weaker side reaches its own critical overlap, its partner is still above its
//   own (the sum is the bound that holds for any split).
#include <epac/models/mdr/detail/mdr_side_force.hpp>

namespace epac {

// d_c = h(a_c), MDR (15) with xi = 1 and (44), (11). Domain: E, gamma, A, B > 0. Returns <= 0.
template <class T>
KOKKOS_INLINE_FUNCTION T mdr_critical_displacement(T E, T gamma, T A, T B) {
  const T a_c = mdr_critical_radius(E, gamma, T(1), A, B);
  return mdr_ellipse_gap(A, B, a_c) - mdr_critical_extension(E, gamma, a_c);
}

// The side's critical apparent overlap delta_c,s for its stored state (delta_o,max, yielded, c_A)
// and growth = R - R_o. gamma: the side's share of the surface energy (<= 0: no adhesion, the
// side holds nothing below its residual overlap).
template <bool Plasticity, class T>
KOKKOS_INLINE_FUNCTION T mdr_side_critical_overlap(const MdrSideConstants<T>& c, T gamma, T R, T growth,
                                                   const MdrSideState<T>& s) {
  T A = T(4) * R, B = T(2) * R, ratio = T(1), delta_p = T(0);  // elastic ellipse (31)
  if (Plasticity && s.yielded != T(0)) {
    const MdrPlasticShape<T> sh = mdr_plastic_shape(c, s.delta_o_max + growth, R, s.c_A);  // (19)
    A = sh.A;
    B = sh.B;
    ratio = sh.ratio;
    delta_p = sh.delta_p;
  }
  if (!(gamma > T(0))) return delta_p;
  return delta_p + ratio * mdr_critical_displacement(c.E_eff, gamma, A, B);
}

}  // namespace epac
