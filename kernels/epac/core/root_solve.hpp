#pragma once
// Bracketed, iteration-capped scalar root solve (safeguarded Newton with bisection fallback).
// Every root solve in a force law goes through here, so each one is bracketed and bounded.
#include <epac/core/kokkos_compat.hpp>

namespace epac {

template <class T>
struct RootResult {
  T x;          // best estimate of the root (always inside the bracket)
  int iters;    // iterations used
  bool converged;
  bool bracketed;  // false: f(lo) and f(hi) had the same sign; x is the end with smaller |f|
};

// Solves f(x) = 0 on [lo, hi]. fdf(x, f, df) writes f(x) and f'(x). Newton steps that leave the
// current bracket, or do not halve it fast enough, are replaced by bisection, so the solve
// converges whenever the bracket holds a sign change, in at most max_iter iterations.
template <class T, class FDF>
KOKKOS_INLINE_FUNCTION RootResult<T> bracketed_newton(const FDF& fdf, T lo, T hi, T rel_tol,
                                                      int max_iter = 100) {
  T flo, dlo, fhi, dhi;
  fdf(lo, flo, dlo);
  fdf(hi, fhi, dhi);
  if (flo == T(0)) return {lo, 0, true, true};
  if (fhi == T(0)) return {hi, 0, true, true};
  if ((flo > T(0)) == (fhi > T(0))) {
    return {math::fabs(flo) < math::fabs(fhi) ? lo : hi, 0, false, false};
  }
  // orient so that f(a) < 0 < f(b)
  T a = flo < T(0) ? lo : hi;
  T b = flo < T(0) ? hi : lo;
  T x = T(0.5) * (lo + hi);
  T dx_old = math::fabs(hi - lo);
  T dx = dx_old;
  T f, df;
  fdf(x, f, df);
  for (int it = 1; it <= max_iter; ++it) {
    const T step_newton = (df != T(0)) ? f / df : T(0);
    const T xn = x - step_newton;
    const bool out = (df == T(0)) || ((xn - a) * (xn - b) > T(0));
    const bool slow = math::fabs(T(2) * step_newton) > math::fabs(dx_old);
    dx_old = dx;
    if (out || slow) {
      dx = T(0.5) * (b - a);
      x = a + dx;
    } else {
      dx = step_newton;
      x = xn;
    }
    fdf(x, f, df);
    if (f == T(0)) return {x, it, true, true};
    if (f < T(0)) a = x; else b = x;
    const T scale = math::max(math::fabs(a), math::fabs(b));
    if (math::fabs(b - a) <= rel_tol * scale || math::fabs(dx) <= rel_tol * math::fabs(x)) {
      return {x, it, true, true};
    }
  }
  return {x, max_iter, false, true};
}

}  // namespace epac
