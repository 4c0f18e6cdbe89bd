#pragma once
// Bracketed, iteration-capped scalar root solve (safeguarded Newton with bisection fallback).
// Every root solve in a force law goes through here, so each one is bracketed and bounded.
//
// The iteration is written once, as a state machine that never calls the function itself
// (NewtonBracket: pure arithmetic, host and device); two thin loops feed it f and f':
// bracketed_newton (host and device, for the force laws) and bracketed_newton_host (host only,
// for parameter set-up with std:: maths, e.g. mdr_parameters.hpp). A host lambda called from a
// __host__ __device__ function draws nvcc diagnostics 20011/20013 (a -Werror device build fails);
// the host loop never enters device code, and both loops take the same steps, bit for bit.
#include <epac/core/kokkos_compat.hpp>

namespace epac {

template <class T>
struct RootResult {
  T x;        // best estimate of the root (always inside the bracket)
  int iters;  // iterations used
  bool converged;
  bool bracketed;  // false: f(lo) and f(hi) had the same sign; x is the end with smaller |f|
};

// One solve's state. Newton steps that leave the current bracket, or do not halve it fast
// enough, are replaced by bisection, so the solve converges whenever the bracket holds a sign
// change, in at most max_iter iterations.
template <class T>
struct NewtonBracket {
  T a, b;  // f(a) < 0 < f(b)
  T x, dx, dx_old;
  T rel_tol;

  // Given f at both ends: returns true and sets `done` when the ends decide the result (a root
  // at an end, or no sign change); otherwise sets up the bracket and the first point x.
  KOKKOS_INLINE_FUNCTION bool start(T lo, T hi, T flo, T fhi, T tol, RootResult<T>& done) {
    rel_tol = tol;
    if (flo == T(0)) {
      done = {lo, 0, true, true};
      return true;
    }
    if (fhi == T(0)) {
      done = {hi, 0, true, true};
      return true;
    }
    if ((flo > T(0)) == (fhi > T(0))) {
      done = {math::fabs(flo) < math::fabs(fhi) ? lo : hi, 0, false, false};
      return true;
    }
    a = flo < T(0) ? lo : hi;  // orient so that f(a) < 0 < f(b)
    b = flo < T(0) ? hi : lo;
    x = T(0.5) * (lo + hi);
    dx_old = math::fabs(hi - lo);
    dx = dx_old;
    return false;
  }
  // Moves x by one Newton or bisection step, from f and f' at the current x.
  KOKKOS_INLINE_FUNCTION void step(T f, T df) {
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
  }
  // With f at the new x: shrinks the bracket; true when converged.
  KOKKOS_INLINE_FUNCTION bool update(T f) {
    if (f == T(0)) return true;
    if (f < T(0))
      a = x;
    else
      b = x;
    const T scale = math::max(math::fabs(a), math::fabs(b));
    return math::fabs(b - a) <= rel_tol * scale || math::fabs(dx) <= rel_tol * math::fabs(x);
  }
};

// Solves f(x) = 0 on [lo, hi]; fdf(x, f, df) writes f(x) and f'(x). Host and device: fdf must be
// callable on the device (a KOKKOS_LAMBDA or a device-callable functor).
template <class T, class FDF>
KOKKOS_INLINE_FUNCTION RootResult<T> bracketed_newton(const FDF& fdf, T lo, T hi, T rel_tol, int max_iter = 100) {
  T flo, fhi, f, df;
  fdf(lo, flo, df);
  fdf(hi, fhi, df);
  NewtonBracket<T> s;
  RootResult<T> done{};
  if (s.start(lo, hi, flo, fhi, rel_tol, done)) return done;
  fdf(s.x, f, df);
  for (int it = 1; it <= max_iter; ++it) {
    s.step(f, df);
    fdf(s.x, f, df);
    if (s.update(f)) return {s.x, it, true, true};
  }
  return {s.x, max_iter, false, true};
}

// The same solve for host-only functions (std:: maths, lambdas in host set-up code).
template <class T, class FDF>
inline RootResult<T> bracketed_newton_host(const FDF& fdf, T lo, T hi, T rel_tol, int max_iter = 100) {  // host
  T flo, fhi, f, df;
  fdf(lo, flo, df);
  fdf(hi, fhi, df);
  NewtonBracket<T> s;
  RootResult<T> done{};
  if (s.start(lo, hi, flo, fhi, rel_tol, done)) return done;
  fdf(s.x, f, df);
  for (int it = 1; it <= max_iter; ++it) {
    s.step(f, df);
    fdf(s.x, f, df);
    if (s.update(f)) return {s.x, it, true, true};
  }
  return {s.x, max_iter, false, true};
}

}  // namespace epac
