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

template <class T>
KOKKOS_INLINE_FUNCTION T jkr_critical_radius_ratio() { return T(0.39685026299204984); }  // 4^(-2/3)
template <class T>
KOKKOS_INLINE_FUNCTION T jkr_critical_overlap_ratio() { return T(-0.47247039371057745); }  // -(3/4) 4^(-1/3)

// x = a/a_0 on the stable branch for d = delta/delta_s >= d_c (returns x_c below d_c).
// Bracket: g(x) = x^2 - sqrt(x) - d is increasing on [x_c, inf); g(x_c) = d_c - d <= 0 and, with
// t = sqrt(max(d,0)), g(t + 1) >= 0 because (t+1)^2 - sqrt(t+1) >= t^2 for t >= 0. At x_c the
// derivative vanishes; bracketed_newton bisects there.
template <class T>
KOKKOS_INLINE_FUNCTION T jkr_contact_radius_ratio(T d, int max_iter = 200) {
  const T xc = jkr_critical_radius_ratio<T>();
  if (!(d > jkr_critical_overlap_ratio<T>())) return xc;
  const T hi = math::sqrt(math::max(d, T(0))) + T(1);
  auto fdf = [d](T x, T& f, T& df) {
    const T sx = math::sqrt(x);  // x >= x_c > 0 inside the bracket
    f = x * x - sx - d;
    df = T(2) * x - T(0.5) / sx;
  };
  const T tol = sizeof(T) == 4 ? T(1e-6) : T(1e-13);
  return bracketed_newton<T>(fdf, xc, hi, tol, max_iter).x;
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
