#pragma once
// Particle pairs in MDR: where the rigid flat between the two sides sits. The flat splits the
// pair's apparent overlap delta into d_0 + d_1 = delta; each side is an MDR particle-flat contact
// (mdr_side_force) and the pair force is the mean of the two side forces (the authors' code,
// docs/models.md "The authors' implementation").
//
// Why a balance and not a geometric split. The authors put the flat on the radical
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
// ellipse, adhesive tension; the exceptions are a side's jump to 0 when it separates and the
// fully plastic force past ~0.94 R, where p_Y falls faster than a_max^2 grows), so its root is
// bracketed: for delta > 0 and non-adhesive sides g(0) <= 0 <= g(delta). Safeguarded Newton with
// the sides' own stiffnesses (MdrSideResult::stiffness): Newton steps while they shrink |g| fast;
// until a sign change is seen, outward steps that double otherwise; once bracketed,
// Newton inside the bracket or else bisection. At most mdr_balance_max_evaluations() pair
// evaluations; every trial inside [min(delta, 0) - (R_0 + R_1), max(delta, 0) + (R_0 + R_1)].
// Converged when |g| is within mdr_balance_tolerance() of the scaled forces or the bracket is
// that narrow relative to the overlaps. Where both forces are 0 (both sides at or below their
// residuals, no adhesion) the guess is kept: no force, no work.
//
// The first guess: the geometric split, a deterministic function of delta and the stored state,
// so that an elastic pair's force stays a single-valued function of delta (closed elastic cycles
// conservative to round-off); once a side has yielded, the last pass's root moved along its
// tangent, d_0 + w (delta_now - delta) with w = lambda_1 k_1 / (lambda_0 k_0 + lambda_1 k_1)
// (d_0, delta, w kept in the pair's history): second order in the step's change of delta, so in
// a quasi-static packing most contacts balance at the first guess (LAMMPS's fcc MDR scene: one
// pair evaluation for 34% of contact-steps over the run, two for 65%; 343 ns per contact-step
// against 250 ns for the geometric split alone, LAMMPS's `granular mdr` 639 ns).
#include <epac/core/kokkos_compat.hpp>
#include <epac/models/mdr/detail/mdr_side_force.hpp>

namespace epac {

template <class T>
KOKKOS_INLINE_FUNCTION constexpr int mdr_balance_max_evaluations() {
  return 64;
}

// Relative tolerance of the balance (of the scaled forces, and of the bracket against the
// overlaps): 1e-10 in double, 8 ulps (9.5e-7) in float. Far below any physical effect; the pair's
// work equals the passive combination of the sides' to that order (elastic pairs exactly: their
// first guess is deterministic), once the sides' forces are moved to the root
// (MdrPairSides::forces_at_root: a split located to the spacing of d_0 leaves a stiff side's
// force off by its stiffness times that, up to 9e-4 of F at stiffness ratios of 1e4 in float).
// Why not a few ulps: from the last pass's split one Newton step
// lands within ~1e-12 of the root in a quasi-static packing, so the tolerance decides between
// two evaluations of the pair per contact and three (measured on LAMMPS's fcc scene: 550 ns per
// contact at 64 ulps).
template <class T>
KOKKOS_INLINE_FUNCTION constexpr T mdr_balance_tolerance() {
  return sizeof(T) >= sizeof(double) ? T(1e-10) : T(8) * T(1.1920929e-7);
}

struct MdrBalanceStats {
  int evaluations = 0;  // pair evaluations (two side forces each), the guess included
  bool converged = false;
  bool bracketed = false;
};

// Finds d_0. `pair(d0)` evaluates both sides at (d0, delta - d0) and returns
// g = lambda_0 F_0 - lambda_1 F_1; pair.scale() then returns lambda_0 |F_0| + lambda_1 |F_1|,
// pair.slope() dg/dd_0 from the sides' stiffnesses, pair.last_x() the last d_0 evaluated. On
// return the pair's last evaluation is at the returned d_0. guess: the first guess of d_0; span:
// R_0 + R_1 (the search limit beyond [min(delta,0), max(delta,0)] and the length scale).
template <class T, class Pair>
KOKKOS_INLINE_FUNCTION T mdr_balance_split(Pair& pair, T delta, T guess, T span, MdrBalanceStats* stats = nullptr) {
  const T tol = mdr_balance_tolerance<T>();
  const int max_eval = mdr_balance_max_evaluations<T>();
  const T lo_lim = math::min(delta, T(0)) - span, hi_lim = math::max(delta, T(0)) + span;
  auto settled = [&](T p, T q) {
    return math::fabs(q - p) <= tol * math::max(math::max(math::fabs(p), math::fabs(q)), math::fabs(delta));
  };
  int n = 0;
  auto finish = [&](T x, bool conv, bool brk) {
    if (stats) *stats = MdrBalanceStats{n, conv, brk};
    return x;
  };

  T x = math::clamp(guess, lo_lim, hi_lim);
  T g = pair(x);
  ++n;
  auto balanced = [&](T gv) { return !(math::fabs(gv) > tol * pair.scale()); };
  // balanced (equal spheres: exactly), or both sides free of force (nothing to balance)
  if (balanced(g)) return finish(x, true, false);

  T xb = x, gb = g;  // best point so far
  T a = x, b = x;    // g(a) < 0 < g(b), valid once have_a / have_b
  bool have_a = g<T(0), have_b = g> T(0);
  if (have_a)
    a = x;
  else
    b = x;
  T last_step = T(1e-3) * math::max(math::fabs(delta), tol * span);  // outward step before a slope
  bool newton_ok = true;                                             // the last Newton step shrank |g| enough
  while (n < max_eval) {
    const bool bracketed = have_a && have_b;
    if (bracketed && settled(a, b)) break;
    // One side without force and the other pushing (or pulling): the root is at or beyond the
    // other side's zero-force overlap, which Newton approaches only geometrically (F ~ d^(3/2)):
    // go there directly (pair.zero_force_split: false when not known, e.g. adhesive contact).
    T xn = x;
    bool newton = false;
    const bool jump = pair.zero_force_split(xn) && xn != x && (!bracketed || (xn - a) * (xn - b) < T(0)) &&
                      xn >= lo_lim && xn <= hi_lim;
    if (!jump) {
      const T slope = pair.slope();
      const T xnewt = x - g / slope;
      newton = newton_ok && slope > T(0) && xnewt == xnewt && (bracketed ? (xnewt - a) * (xnewt - b) < T(0) : true);
      if (newton) {
        xn = xnewt;
      } else if (bracketed) {
        xn = T(0.5) * (a + b);
      } else {
        // no slope to trust and no bracket yet: step outward, growing
        const T dir = g > T(0) ? T(-1) : T(1);
        last_step = T(2) * last_step;
        xn = x + dir * last_step;
      }
      if (!bracketed) {
        // before a sign change: within the search limits (a Newton step that does not halve |g|
        // hands over to the growing outward steps)
        last_step = math::max(last_step, math::fabs(xn - x));
        xn = math::clamp(xn, lo_lim, hi_lim);
        if (xn == x) break;  // at the search limit without a sign change
      }
    }
    const T gn = pair(xn);
    ++n;
    newton_ok = !newton || math::fabs(gn) <= T(0.5) * math::fabs(g);
    x = xn;
    g = gn;
    if (math::fabs(g) < math::fabs(gb)) {
      xb = x;
      gb = g;
    }
    if (balanced(g)) return finish(x, true, have_a && have_b);
    if (g < T(0)) {
      a = x;
      have_a = true;
    } else {
      b = x;
      have_b = true;
    }
  }
  // bracket settled (or budget spent, or no sign change within the limits): the best point
  if (pair.last_x() != xb) pair(xb);
  return finish(xb, have_a && have_b && settled(a, b), have_a && have_b);
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
  T a_fac = T(1);              // adhesive radius factor (MdrAdhesiveRadius)
  bool with_stiffness = true;  // false: one evaluation at a split not solved for (r[s].stiffness 0)
  MdrSideState<T> start[2];    // the step's starting states
  MdrSideState<T> st[2];       // after the last evaluation
  MdrSideResult<T> r[2];       // of the last evaluation
  T d[2];                      // overlaps of the last evaluation
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
      r[s] = mdr_side_force<Plasticity, Adhesion>(*c[s], gamma[s], xi, d[s], R[s], growth[s], st[s], a_fac,
                                                  with_stiffness);
    }
    return lambda[0] * r[0].F - lambda[1] * r[1].F;
  }
  KOKKOS_INLINE_FUNCTION T scale() const { return lambda[0] * math::fabs(r[0].F) + lambda[1] * math::fabs(r[1].F); }
  // dg/dd_0 from the sides' stiffnesses dF_s/dd_s (MdrSideResult::stiffness)
  KOKKOS_INLINE_FUNCTION T slope() const { return lambda[0] * r[0].stiffness + lambda[1] * r[1].stiffness; }
  KOKKOS_INLINE_FUNCTION T last_x() const { return x_last; }
  // After the solve: the sides' forces at the root, to first order from the last evaluation
  // (d_0): with g and the slope of that evaluation the root is d_0 - s, s = g / slope, so
  // F_0 -= k_0 s and F_1 += k_1 s (lambda_0 F_0 = lambda_1 F_1 then holds to second order in s).
  // Why: the root is only located to the spacing of d_0 (float: d_0 ~ delta, a spacing of
  // 6e-8 delta; the solve stops within 8 spacings, or on a Newton step below one), and a stiff
  // side's force moves by its
  // k times that spacing: a soft elastic side on a stiff yielded one (k_1/k_0 ~ 1e4) carried
  // |F_0 - F_1| up to 9e-4 of F at the returned split, so the mean force (the pair's) was off the
  // balanced force by half that, in a way that depended on the warm start: on the fuzz's
  // quasi-static cycles of such pairs (nearly elastic, dissipating less than that) the pair
  // returned up to 2.1e-4 more work than it took (docs/stability.md). At the root the pair force
  // is the balanced force, whose error is the float round-off of the soft side's force. Applied
  // only when the correction stays within the solve's resolution, tol max(|d_0|, |delta|) (a
  // solve stopped by its budget, or a side without stiffness, e.g. separated, keeps its forces).
  KOKKOS_INLINE_FUNCTION void forces_at_root(T tol) {
    const T k0 = r[0].stiffness, k1 = r[1].stiffness;
    if (!(k0 > T(0) && k1 > T(0))) return;
    const T g = lambda[0] * r[0].F - lambda[1] * r[1].F;
    const T step = g / (lambda[0] * k0 + lambda[1] * k1);  // d_0 - d_0,root
    if (!(math::fabs(step) <= tol * math::max(math::fabs(d[0]), math::fabs(delta)))) return;
    r[0].F -= k0 * step;
    r[1].F += k1 * step;
  }
  // Where to put d_0 when one side is free of force (F = 0) and the other is not: the other
  // side's zero-force overlap (its residual delta_p once yielded, else 0), so that both forces
  // vanish, or, if that compresses the free side, a bracket end. False where it is not known: no
  // side free, or the loaded side holds an adhesive radius (its force is not 0 at delta_p).
  KOKKOS_INLINE_FUNCTION bool zero_force_split(T& x) const {
    for (int s = 0; s < 2; ++s) {
      const int o = 1 - s;  // s is free, o carries force
      if (r[s].F == T(0) && r[o].F != T(0) && !(Adhesion && st[o].a_adh > T(0))) {
        const T z = (Plasticity && st[o].yielded != T(0)) ? st[o].delta_p : T(0);
        x = o == 0 ? z : delta - z;
        return true;
      }
    }
    return false;
  }
};

}  // namespace epac
