#pragma once
// JKR contact of two elastic spheres in dimensionless form (Nan Appendix B, (B1)-(B5)).
// Scales: a_0 = (2 pi Gamma R*^2 / E*)^(1/3), the contact radius at zero overlap (B5);
// delta_s = a_0^2 / R*; f_ce = 1.5 pi Gamma R*. With x = a/a_0 and d = delta/delta_s:
//   d = x^2 - sqrt(x)                        (B3)
//   f / f_ce = 16/9 x^3 - 8/3 x^(3/2)        (B1), since 4 E* a_0^3/(3 R*) = 16/9 f_ce and
//                                             sqrt(8 pi Gamma E*) a_0^(3/2) = 8/3 f_ce
// The stable branch starts at the displacement-controlled critical point x_c = 4^(-2/3)
// (dd/dx = 0), d_c = -(3/4) 4^(-1/3): there the contact breaks with f = -5/9 f_ce. The
// force-controlled pull-off, min f = -f_ce, is at x^(3/2) = 3/4.
#include <epac/core/root_solve.hpp>
#include <epac/core/simd_lanes.hpp>

namespace epac {

template <class T>
struct JkrScales {
  T a0;       // contact radius at zero overlap, (B5)
  T delta_s;  // overlap scale a0^2 / R*
  T f_ce;     // pull-off force 1.5 pi Gamma R*
};

// Domains: Gamma > 0, R* > 0, E* > 0 (cbrt argument positive).
template <class T>
KOKKOS_INLINE_FUNCTION JkrScales<T> jkr_scales(T gamma, T R_star, T E_star) {
  const T pi = constants<T>::pi;
  JkrScales<T> s;
  // (2 pi Gamma / E*)^(1/3) R*^(2/3): cube roots taken separately so float does not underflow
  s.a0 = math::cbrt(T(2) * pi * gamma / E_star) * math::cbrt(R_star * R_star);
  s.delta_s = s.a0 * s.a0 / R_star;
  s.f_ce = T(1.5) * pi * gamma * R_star;
  return s;
}

// The same scales from the pair's precomputed (2 pi Gamma / E*)^(1/3) and the contact's
// r13 = R*^(1/3) (the model keeps it in history: no cube root per step). R* > 0.
template <class T>
KOKKOS_INLINE_FUNCTION JkrScales<T> jkr_scales_from_root(T a0_coeff, T r13, T gamma, T R_star) {
  JkrScales<T> s;
  s.a0 = a0_coeff * r13 * r13;
  s.delta_s = s.a0 * s.a0 / R_star;
  s.f_ce = T(1.5) * constants<T>::pi * gamma * R_star;
  return s;
}

template <class T>
KOKKOS_INLINE_FUNCTION T jkr_critical_radius_ratio() {
  return T(0.39685026299204984);
}  // 4^(-2/3)
template <class T>
KOKKOS_INLINE_FUNCTION T jkr_critical_overlap_ratio() {
  return T(-0.47247039371057745);
}  // -(3/4) 4^(-1/3)

// x = a/a_0 on the stable branch for d = delta/delta_s >= d_c (returns x_c below d_c), in closed
// form (no iteration; LAMMPS's granular jkr also solves it in closed form). With y = sqrt(x), (B3)
// is the quartic y^4 - y - d = 0. Ferrari: (y^2 + m)^2 = 2m y^2 + y + m^2 + d is a perfect square
// in y when m solves the resolvent cubic m^3 + d m - 1/8 = 0, whose real root (Cardano) is
// m = u - d/(3u), u = cbrt(1/16 + S), S = sqrt(1/256 + d^3/27). Written as
// m = (1/8) / (u^2 + u v + v^2), v = d/(3u) (the identity u^3 - v^3 = 1/8), it has no cancellation
// at large d, where m -> 1/(8d). The stable (largest) root is then y = (s + sqrt(2/s - s^2))/2,
// s = sqrt(2m). Domains: S's argument is >= 0 for d >= d_c (it is 0 exactly at d_c, where the
// two roots merge and 2/s - s^2 = 0): both clamped at 0 against round-off; u >= cbrt(1/16) > 0;
// m > 0 so s > 0. One Newton step on the quartic polishes the last bits where its slope
// 4y^3 - 1 is well away from 0 (it vanishes at d_c). Beyond d = 1e6, d^3 would overflow float:
// there y starts at d^(1/4) and two Newton steps converge (relative correction ~ d^(-3/4)/4).
template <class T>
KOKKOS_INLINE_FUNCTION T jkr_contact_radius_ratio(T d) {
  const T xc = jkr_critical_radius_ratio<T>();
  if (!(d > jkr_critical_overlap_ratio<T>())) return xc;
  T y;
  if (d > T(1e6)) {
    y = math::sqrt(math::sqrt(d));
    for (int it = 0; it < 2; ++it) y -= (y * y * y * y - y - d) / (T(4) * y * y * y - T(1));  // 4y^3 - 1 > 100
  } else {
    const T S = math::sqrt_nonneg(T(1) / T(256) + d * d * d / T(27));
    const T u = math::cbrt(T(1) / T(16) + S);
    const T v = d / (T(3) * u);
    const T m = T(0.125) / (u * u + u * v + v * v);  // denominator >= (3/4) u^2 > 0
    const T s = math::sqrt(T(2) * m);
    y = T(0.5) * (s + math::sqrt_nonneg(T(2) / s - s * s));
    const T slope = T(4) * y * y * y - T(1);
    if (slope > T(0.5)) y -= (y * y * y * y - y - d) / slope;
  }
  return math::max(y * y, xc);
}

// y = sqrt(a/a_0) on the stable branch of (B3), y^4 - y - d = 0, warm-started from y_guess (the
// contact's last y; <= 0 for none). Newton from a nearby root converges quadratically while the
// slope 4y^3 - 1 stays away from 0 (it vanishes at the critical point y_c^3 = 1/4); each iterate
// must keep the slope above 1/2 (well inside the stable branch), and after a correction c the
// next error is about (f''/(2 f')) c^2 = 6 y^2 c^2 / (4y^3 - 1), so the iterate is accepted when
// that is below 2 eps y. At most 3 iterations; anything else (no guess, d at or below d_c, a
// guess that leaves the branch, no convergence) takes the closed form, so the result is the
// closed form's root to within a few ulps either way. In a contact that moves little per step this
// costs one or two divisions instead of two cube roots, three square roots and four divisions.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T jkr_contact_radius_root(T d, T y_guess) {
  if (y_guess > T(0) && d > jkr_critical_overlap_ratio<T>() && d <= T(1e6)) {
    const T tol = T(2) * constants<T>::epsilon;
    T y = y_guess;
    for (int it = 0; it < 3; ++it) {
      const T y3 = y * y * y;
      const T slope = T(4) * y3 - T(1);
      if (!(slope > T(0.5))) break;  // off the stable branch's well-conditioned part
      const T c = (y3 * y - y - d) / slope;
      y -= c;
      if (T(6) * y * c * c <= tol * slope) {
        if (T(4) * y * y * y - T(1) > T(0.5)) return y;
        break;
      }
    }
  }
  return math::sqrt(jkr_contact_radius_ratio(d));
}

// jkr_contact_radius_root's warm-started Newton iteration without branches, for contacts in lanes
// (compute/pair_lanes.hpp): the same iterates, each lane's y frozen at the iterate the scalar
// form returns. `converged` is false where the scalar form would take the closed form (no guess,
// d outside (d_c, 1e6], a slope at or below 1/2, a converged iterate off the stable branch, no
// convergence in 3 iterations); y is then meaningless and the caller takes the scalar form.
// Divisions only by slopes > 1/2 (other lanes divide by 1).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T jkr_contact_radius_lane(T d, T y_guess, bool& converged) {
  const T tol = T(2) * constants<T>::epsilon;
  T y = y_guess;
  bool live = (y_guess > T(0)) & (d > jkr_critical_overlap_ratio<T>()) & (d <= T(1e6));
  bool done = false;
  for (int it = 0; it < 3; ++it) {
    const T y3 = y * y * y;
    const T slope = T(4) * y3 - T(1);
    live = live & (slope > T(0.5));
    const T c = (y3 * y - y - d) / lane_select(live, slope, T(1));
    const T next = y - c;
    const bool small = T(6) * next * c * c <= tol * slope;
    const bool stable = T(4) * next * next * next - T(1) > T(0.5);
    y = lane_select(live, next, y);
    done = done | (live & small & stable);
    live = live & !small;  // a converged iterate ends the iteration, on or off the branch
  }
  converged = done;
  return y;
}

// f/f_ce at y = sqrt(x), (B1): 16/9 y^6 - 8/3 y^3 (no square root).
template <class T>
KOKKOS_INLINE_FUNCTION T jkr_force_ratio_of_root(T y) {
  const T y3 = y * y * y;
  return T(16) / T(9) * y3 * y3 - T(8) / T(3) * y3;
}

// f/f_ce at x, (B1).
template <class T>
KOKKOS_INLINE_FUNCTION T jkr_force_ratio(T x) {
  return T(16) / T(9) * x * x * x - T(8) / T(3) * x * math::sqrt(x);
}

// Tangent stiffness df/d(delta) of the JKR curve, (B2): 2 E* a (sqrt(f_H/f_ce) - 1)/(sqrt(f_H/f_ce) - 1/3)
// with sqrt(f_H/f_ce) = 4/3 x^(3/2) (B4). Infinite at x_c (the critical point) and negative between
// x_c and the pull-off point; the model uses 2 E* a instead (see jkr.hpp). Domain: x != x_c.
template <class T>
KOKKOS_INLINE_FUNCTION T jkr_tangent_stiffness(T x, T a0, T E_star) {
  const T r = T(4) / T(3) * x * math::sqrt(x);
  return T(2) * E_star * a0 * x * (r - T(1)) / (r - T(1) / T(3));
}

}  // namespace epac
