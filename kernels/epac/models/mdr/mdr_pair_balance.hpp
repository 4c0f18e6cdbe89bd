#pragma once
// Particle pairs in MDR: where the rigid flat between the two sides sits. The flat splits the
// pair's apparent overlap delta into d_0 + d_1 = delta; each side is an MDR particle-flat contact
// (mdr_side_force) and the pair force is the mean of the two side forces (the authors' code,
// mdr-reference-notes.md "Particle pairs").
//
// Why a balance and not a geometric split (issue 10). The authors put the flat on the radical
// plane while loading and interpolate it towards the sides' residual overlaps while unloading
// (mdr_pair_split.hpp keeps that rule: it is the first guess here). A prescribed split with the
// mean force is not work-conjugate: F d(delta) differs from sum_s F_s d(d_s) whenever F_0 != F_1,
// so a load-unload cycle of a yielded unequal pair returned more work than it took on about 1% of
// random cycles (up to 7-19% of the cycle's work).
//
// epac puts the flat where the sides' scaled forces balance:
//     lambda_0 F_0(d_0) = lambda_1 F_1(delta - d_0),   lambda_s = R_s E_o / ((R_0 + R_1)(E_0 + E_1))
// (E_s: the side's E_eff, E_o: the other side's; lambda_s in (0, 1), the scale is irrelevant).
// - Passive by construction: with G the balanced value, F_s = G / lambda_s and the mean force is
//   F = kappa G, kappa = (1/lambda_0 + 1/lambda_1) / 2, so F d(delta) = kappa G (d d_0 + d d_1)
//   = sum_s kappa lambda_s F_s d d_s: the pair's work is a positive constant combination of the
//   sides' works, and each side (elastic, plastic, adhesive) never returns more than it took.
// - The same physics as the radical plane where that one is right: for the elastic sides
//   F_s = 4/3 E_s sqrt(R_s) d_s^(3/2) (small d/R) the balance gives R_s d_s equal on both sides,
//   d_s = delta R*/R_s, which is the radical plane to first order in delta/R (the radical plane's
//   own higher-order terms are geometry, not mechanics). E_s drops out of lambda_s F_s, so the
//   elastic split is geometric whatever the moduli, as in the authors' code, and the mean force is
//   Hertz's for equal moduli.
// - Unloading: a side that yielded sits at its residual overlap once its force is gone; the flat
//   follows the forces, so the pair separates at delta = delta_p,0 + delta_p,1 (as the authors'
//   interpolation intends) without a prescribed path.
// - Two equal spheres of one material with equal histories: the first guess (delta/2) balances
//   exactly and the solve costs nothing beyond the guess.
//
// The solve: g(d_0) = lambda_0 F_0(d_0) - lambda_1 F_1(delta - d_0) is non-decreasing in d_0
// (each side's force rises with its overlap on every branch: loading, unloading on the fixed
// ellipse, adhesive tension; the one exception is a side's jump to 0 when it separates), so its
// root is bracketed: for delta > 0 and non-adhesive sides g(0) <= 0 <= g(delta). Steps: the first
// guess, one Newton step with the sides' contact stiffnesses 2 E_s a_s, secant steps outward
// (growing, bounded) until g changes sign, then Illinois regula falsi inside the bracket; at most
// mdr_balance_max_evaluations() evaluations of the pair, and every point stays inside
// [min(delta, 0) - (R_0 + R_1), max(delta, 0) + (R_0 + R_1)]. Converged when g = 0, when |g| is
// round-off of the scaled forces, or when the bracket is a few ulps of the overlaps wide. Where both forces are 0
// (both sides at or below their residuals, no adhesion) the guess is kept: no force, no work.
#include <epac/core/kokkos_compat.hpp>
#include <epac/models/mdr/mdr_side_force.hpp>

namespace epac {

template <class T>
KOKKOS_INLINE_FUNCTION constexpr int mdr_balance_max_evaluations() { return 64; }

// Relative tolerance of the balance: a few ulps of the scaled forces (double 8.9e-16, float 4.8e-7).
template <class T>
KOKKOS_INLINE_FUNCTION constexpr T mdr_balance_tolerance() {
  return sizeof(T) >= sizeof(double) ? T(4) * T(2.220446049250313e-16) : T(4) * T(1.1920929e-7);
}

struct MdrBalanceStats {
  int evaluations = 0;  // pair evaluations (two side forces each), the guess included
  bool converged = false;
  bool bracketed = false;
};

// Finds d_0. `pair(d0)` evaluates both sides at (d0, delta - d0) and returns
// g = lambda_0 F_0 - lambda_1 F_1; pair.scale() then returns lambda_0 |F_0| + lambda_1 |F_1| and
// pair.slope() an estimate of dg/dd_0 (> 0, or 0 when unknown); the pair object keeps the side
// results of its last evaluation, and on return its last evaluation is at the returned d_0.
// guess: the geometric split's d_0; span: R_0 + R_1 (the search limit beyond [min(delta,0),
// max(delta,0)] and the absolute length scale).
template <class T, class Pair>
KOKKOS_INLINE_FUNCTION T mdr_balance_split(Pair& pair, T delta, T guess, T span, MdrBalanceStats* stats = nullptr) {
  const T tol = mdr_balance_tolerance<T>();
  const int max_eval = mdr_balance_max_evaluations<T>();
  const T lo_lim = math::min(delta, T(0)) - span, hi_lim = math::max(delta, T(0)) + span;
  // bracket width below which d_0 is settled: a few ulps of the overlaps involved (relative to
  // delta and the bracket ends, not to the radii: overlaps can be 1e-6 R in a DEM step)
  auto settled = [&](T p, T q) {
    return math::fabs(q - p) <= tol * math::max(math::max(math::fabs(p), math::fabs(q)), math::fabs(delta));
  };

  T x0 = math::clamp(guess, lo_lim, hi_lim);
  T g0 = pair(x0);
  int n = 1;
  auto finish = [&](T x, bool conv, bool brk) {
    if (stats) *stats = MdrBalanceStats{n, conv, brk};
    return x;
  };
  // balanced already (equal spheres), or both sides free of force (nothing to balance)
  if (g0 == T(0) || !(math::fabs(g0) > tol * pair.scale())) return finish(x0, true, false);

  // best point so far, to return when the iteration budget runs out
  T xb = x0, gb = g0;
  T a = x0, ga = g0;  // a point with g < 0 (valid once have_a)
  T b = x0, gbr = g0;  // a point with g > 0 (valid once have_b)
  bool have_a = g0 < T(0), have_b = g0 > T(0);

  // phase 1: Newton from the guess, then secant steps outward until g changes sign
  T slope = pair.slope();
  T step;
  if (slope > T(0)) step = -g0 / slope;
  else step = (g0 > T(0) ? T(-1) : T(1)) * T(1e-3) * math::max(math::fabs(delta), tol * span);
  T x1 = x0, g1 = g0;
  while (!(have_a && have_b) && n < max_eval) {
    T xn = math::clamp(x1 + step, lo_lim, hi_lim);
    if (xn == x1) break;  // at the search limit without a sign change
    const T gn = pair(xn);
    ++n;
    if (gn == T(0) || !(math::fabs(gn) > tol * pair.scale())) return finish(xn, true, true);
    if (math::fabs(gn) < math::fabs(gb)) { xb = xn; gb = gn; }
    if (gn < T(0)) { a = xn; ga = gn; have_a = true; }
    else { b = xn; gbr = gn; have_b = true; }
    if (have_a && have_b) break;
    // same sign as before: continue outward; the secant through the last two points says how
    // far, at least the last step, at most four times it
    const T dir = gn > T(0) ? T(-1) : T(1);
    const T last = math::fabs(xn - x1);
    T len = T(2) * last;
    const T dg = gn - g1;
    if (dg != T(0)) {
      const T sec = -gn * (xn - x1) / dg;  // secant step
      if (sec * dir > T(0)) len = math::clamp(math::fabs(sec) * T(1.5), last, T(4) * last);
    }
    x1 = xn; g1 = gn;
    step = dir * len;
  }
  if (!(have_a && have_b)) {
    if (pair.last_x() != xb) pair(xb);
    return finish(xb, false, false);
  }

  // phase 2: Illinois regula falsi on [a, b] (g(a) < 0 < g(b); a and b in either order)
  int side = 0;  // which end the last step replaced (-1: a, +1: b), for the Illinois halving
  while (n < max_eval) {
    if (settled(a, b)) break;
    T xn = (a * gbr - b * ga) / (gbr - ga);  // gbr > 0 > ga: denominator > 0
    // keep strictly inside; fall back to the midpoint at an end (round-off)
    if (!((xn - a) * (xn - b) < T(0))) xn = T(0.5) * (a + b);
    const T gn = pair(xn);
    ++n;
    if (math::fabs(gn) < math::fabs(gb)) { xb = xn; gb = gn; }
    if (gn == T(0) || !(math::fabs(gn) > tol * pair.scale())) return finish(xn, true, true);
    if (gn < T(0)) {
      a = xn; ga = gn;
      if (side == -1) gbr *= T(0.5);  // b kept twice in a row: halve its weight (Illinois)
      side = -1;
    } else {
      b = xn; gbr = gn;
      if (side == 1) ga *= T(0.5);
      side = 1;
    }
  }
  // bracket settled (or budget spent): the best point evaluated
  if (pair.last_x() != xb) pair(xb);
  return finish(xb, settled(a, b), true);
}

// The two sides of a pair at trial splits, for mdr_balance_split: each evaluation starts from
// the sides' states at the beginning of the step (trial evaluations never commit), and keeps the
// results and advanced states of the last one. Side s: constants c[s], surface energy share
// gamma[s], radius R[s], growth R - R_o growth[s].
template <class T, bool Plasticity, bool Adhesion>
struct MdrPairSides {
  const MdrSideConstants<T>* c[2];
  T gamma[2], R[2], growth[2], lambda[2];
  T xi, delta;
  MdrSideState<T> start[2];  // the step's starting states
  MdrSideState<T> st[2];     // after the last evaluation
  MdrSideResult<T> r[2];     // of the last evaluation
  T d[2];                    // overlaps of the last evaluation
  T x_last;

  // lambda_s = R_s E_o / ((R_0 + R_1)(E_0 + E_1)), see the header. R_s > 0, E_eff > 0 (create).
  KOKKOS_INLINE_FUNCTION void set_weights() {
    const T inv = T(1) / ((R[0] + R[1]) * (c[0]->E_eff + c[1]->E_eff));
    lambda[0] = R[0] * c[1]->E_eff * inv;
    lambda[1] = R[1] * c[0]->E_eff * inv;
  }
  KOKKOS_INLINE_FUNCTION T operator()(T d0) {
    x_last = d0;
    d[0] = d0;
    d[1] = delta - d0;
    for (int s = 0; s < 2; ++s) {
      st[s] = start[s];
      r[s] = mdr_side_force<Plasticity, Adhesion>(*c[s], gamma[s], xi, d[s], R[s], growth[s], st[s]);
    }
    return lambda[0] * r[0].F - lambda[1] * r[1].F;
  }
  KOKKOS_INLINE_FUNCTION T scale() const { return lambda[0] * math::fabs(r[0].F) + lambda[1] * math::fabs(r[1].F); }
  // dg/dd_0 from the contact stiffnesses dF_s/dd_s ~ 2 E_s a_s (exact on the elastic branch; an
  // estimate elsewhere, only the first step uses it)
  KOKKOS_INLINE_FUNCTION T slope() const {
    return T(2) * (lambda[0] * c[0]->E_eff * r[0].a + lambda[1] * c[1]->E_eff * r[1].a);
  }
  KOKKOS_INLINE_FUNCTION T last_x() const { return x_last; }
};

}  // namespace epac
