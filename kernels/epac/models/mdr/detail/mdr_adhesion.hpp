#pragma once
// MDR adhesion (Part I, Section 6 and Appendix E "forceAdhesion"): the springs under the indenter
// stick to it; on retraction the outer springs stretch until they reach Delta l(a) (11), then
// detach (the contact radius a shrinks by (48)), and the contact separates below the critical
// radius a_c of (15). The contact radius a is per-contact history.
//
// Conventions (docs/models.md, "Reading Part I where its text is ambiguous"):
// - "No tensile springs" holds when the non-adhesive half-width at the current depth,
//   a_na = (B/A) sqrt(d (A - d)), reaches the stored a (all springs in compression). Then
//   a = a_na (Appendix E's "a = B/2" is this at d = A/2, the plastic-loading depth).
// - Otherwise a keeps its stored value while the edge springs' extension g_1D(a) - d stays within
//   Delta l(a) (the paper's rule; not the authors' 0.99 a_na trick, whose pull-off force depends
//   on the step). Section 6 writes the tests with w_1D(a) > 0 for tension, but by (45)
//   w_1D = d - g_1D(a) < 0 in tension: the extension g_1D(a) - d is compared with Delta l.
// - Beyond Delta l the new a solves (48) d + Delta l(a) - g_1D(a) = 0 on [a_c, a_old] (the stable
//   root: d/da (g_1D - Delta l) > 0 there, Appendix A.3); no root there means separation.
// - After separation a = 0; adhesion re-forms only once the indenter is pressed in again (d > 0
//   gives a_na > 0 = a, the "no tensile springs" state).
// - a_fac (MdrAdhesiveRadius::authors: 0.99, the authors' code; 1 by default): the no-tension
//   state stores a = a_fac a_na, and a stored radius is used at most as a_fac B/2, so tension
//   starts only once a_na has fallen below a_fac times its largest value.
#include <epac/core/root_solve.hpp>
#include <epac/models/mdr/detail/mdr_ellipse.hpp>

namespace epac {

template <class T>
KOKKOS_INLINE_FUNCTION T mdr_root_tolerance() {
  return sizeof(T) >= sizeof(double) ? T(1e-13) : T(2e-6);
}

// MDR (11): critical extension Delta l(a) = sqrt(2 pi a gamma / E). Domain a >= 0 (clamped).
template <class T>
KOKKOS_INLINE_FUNCTION T mdr_critical_extension(T E, T gamma, T a) {
  return math::sqrt_nonneg(T(2) * constants<T>::pi * a * gamma / E);
}

// MDR (15) with g_1D of (44): the critical radius a_c where d g_1D/da = xi sqrt(pi gamma/(2 E a)).
// Squaring gives the cubic 2 E A^2 a^3 + xi^2 pi gamma B^2 a^2 - xi^2 pi gamma B^4/4 = 0 (xi = 1 is
// the cubic of docs/models.md "Reading Part I"; xi = 3 replaces gamma by 9 gamma). With a = u B/2 it reads
//   lambda u^3 + u^2 - 1 = 0,   lambda = E A^2 / (xi^2 pi gamma B),
// increasing in u >= 0 with one root in (0, 1]: lambda u^3 <= 1 and u^2 <= 1 give
// u <= min(1, lambda^(-1/3)), and max(lambda u^3, u^2) >= 1/2 gives u >= min((2 lambda)^(-1/3),
// 2^(-1/2)); that bracket (ratio <= 2^(1/3)) goes to bracketed_newton. Domain: gamma > 0, A, B > 0.
template <class T>
KOKKOS_INLINE_FUNCTION T mdr_critical_radius(T E, T gamma, T xi, T A, T B) {
  const T lambda = E * A * A / (xi * xi * constants<T>::pi * gamma * B);
  const T cl = math::cbrt(lambda);  // lambda > 0
  const T hi = math::min(T(1), T(1) / cl);
  const T lo = math::min(T(1) / (math::cbrt(T(2)) * cl), T(0.7071067811865476));
  auto f = [lambda](T u, T& fv, T& df) {
    fv = (lambda * u + T(1)) * u * u - T(1);
    df = (T(3) * lambda * u + T(2)) * u;
  };
  const RootResult<T> r = bracketed_newton<T>(f, lo, hi, mdr_root_tolerance<T>(), 100);
  return T(0.5) * B * r.x;
}

// MDR (48): the contact radius a in [a_lo, a_hi] with d + Delta l(a) - g_1D(a) = 0, where
// h(a) = g_1D(a) - Delta l(a) - d increases on [a_c, B/2]. Caller guarantees h(a_lo) <= 0 <= h(a_hi).
template <class T>
KOKKOS_INLINE_FUNCTION T mdr_peeling_radius(T E, T gamma, T A, T B, T d, T a_lo, T a_hi) {
  auto f = [=](T a, T& fv, T& df) {
    const T dl = mdr_critical_extension(E, gamma, a);
    fv = mdr_ellipse_gap(A, B, a) - dl - d;
    // d Delta l / da = Delta l / (2 a); a >= a_lo = a_c > 0
    df = mdr_ellipse_gap_slope(A, B, a) - (a > T(0) ? T(0.5) * dl / a : T(0));
  };
  return bracketed_newton<T>(f, a_lo, a_hi, mdr_root_tolerance<T>(), 100).x;
}

enum MdrAdhesionState : int {
  kMdrNoTension = 1,      // all springs compressed (or no contact)
  kMdrTensionWithin = 2,  // edge springs stretched less than Delta l; a kept
  kMdrPeeling = 3,        // edge springs at Delta l; a from (48)
  kMdrSeparated = 4       // a fell below a_c: full separation this step
};

template <class T>
struct MdrAdhesiveForce {
  T F;  // MDR force (positive = compressive)
  T a;  // new contact radius (history)
  int state;
};

// "forceAdhesion" of Appendix E. E: the side's E_eff; gamma > 0; xi of (15); A, B: current ellipse;
// d: transformed elastic displacement delta_1D^e; a_old: stored contact radius.
// Force with tension: F = F_na(g_1D(a)) + 2 E (d - g_1D(a)) a, MDR (46)-(47).
// States 2-4 (springs in tension), kept out of the inlined hot path: a_na < a_old.
template <class T>
KOKKOS_INLINE_FUNCTION MdrAdhesiveForce<T> mdr_adhesive_force_tension(T E, T gamma, T xi, T A, T B, T d, T a_old,
                                                                      T a_fac = T(1)) {
  const T a_stored = math::min(a_old, a_fac * T(0.5) * B);  // a <= B/2 (guards the sqrt of (44))
  const T g_old = mdr_ellipse_gap(A, B, a_stored);
  const T extension = g_old - d;  // > 0 here since a_na < a_old
  if (extension <= mdr_critical_extension(E, gamma, a_stored)) {
    // state 2: tension within Delta l, a kept
    const T F = mdr_ellipse_force(E, A, B, g_old) - T(2) * E * extension * a_stored;
    return {F, a_stored, kMdrTensionWithin};
  }
  // state 3: edge springs beyond Delta l: peel to the root of (48) in [a_c, a_old]
  const T a_c = mdr_critical_radius(E, gamma, xi, A, B);
  if (a_stored <= a_c) return {T(0), T(0), kMdrSeparated};
  const T h_c = mdr_ellipse_gap(A, B, a_c) - mdr_critical_extension(E, gamma, a_c) - d;
  if (h_c > T(0)) return {T(0), T(0), kMdrSeparated};  // no equilibrium with a >= a_c
  const T a = mdr_peeling_radius(E, gamma, A, B, d, a_c, a_stored);
  const T g = mdr_ellipse_gap(A, B, a);
  const T F = mdr_ellipse_force(E, A, B, g) - T(2) * E * (g - d) * a;
  return {F, a, kMdrPeeling};
}

template <class T>
KOKKOS_FORCEINLINE_FUNCTION MdrAdhesiveForce<T> mdr_adhesive_force(T E, T gamma, T xi, T A, T B, T d, T a_old,
                                                                   T a_fac = T(1)) {
  const T a_na = mdr_ellipse_contact_radius(A, B, d);
  if (a_na >= math::min(a_old, a_fac * T(0.5) * B)) {
    // state 1: no tensile springs, the non-adhesive law (a_na = 0 and d <= 0: no contact)
    return {mdr_ellipse_force(E, A, B, d), a_fac * a_na, kMdrNoTension};
  }
  return mdr_adhesive_force_tension(E, gamma, xi, A, B, d, a_old, a_fac);
}

}  // namespace epac
