#pragma once
// The MDR normal force of one contact side: a particle of apparent radius R against a rigid flat
// at apparent overlap delta (Part I, Sections 5-7 and Appendix E). Particle pairs evaluate two
// sides (mdr_pair_split.hpp); walls one.
//
// Regimes:
// - elastic: the ellipse A = 4R, B = 2R (31) at depth delta_1D^e = delta; force (30);
// - switch (5.6.5): on loading, once delta/R exceeds x_yield = delta_Y/R (the root of the yield
//   equation, mdr_parameters.hpp), the side is fully plastic for good; c_A (43) from delta_Y, the
//   force of that step from the current delta (notes: "delta = delta_Y" means c_A only);
// - fully plastic: a_max (36), A, B (28), p_Y (16)+(21), delta_R (34), delta_1D^e (35); force (30);
//   unloading and reloading below delta_max run on the fixed ellipse of delta_max, so they retrace.
#include <epac/models/mdr/detail/mdr_adhesion.hpp>
#include <epac/models/mdr/detail/mdr_ellipse.hpp>
#include <epac/models/mdr/mdr_parameters.hpp>

namespace epac {

// Lower bound of r = 1 + delta_R / delta_1D,max^e, the factor of (35). r -> 0 as z_R -> 0
// (delta_max -> R + A/2: delta_R/(A/2) -> -(1-nu) E_eff/(2G) = -1), where (35) would divide by 0
// and the unloading stiffness 1/r diverge; the authors' code aborts there on NaN. r stays above
// 0.09 for delta_max/R <= 0.75 and any E/Y >= 6.25, so the floor acts only beyond delta_max ~ 0.95 R.
template <class T>
KOKKOS_INLINE_FUNCTION constexpr T mdr_min_recovery_ratio() {
  return T(0.01);
}

// Per-side history (fields present only for enabled effects; see mdr_model.hpp).
template <class T>
struct MdrSideState {
  T delta_o_max = 0;   // running maximum of delta_o = delta - (R - R_o); delta_max by (19)
  T yielded = 0;       // 0 elastic, 1 fully plastic
  T c_A = 0;           // area intercept (43)
  T delta_p = 0;       // residual (plastic) overlap: delta where delta_1D^e = 0
  T a_adh = 0;         // adhesive contact radius (Section 6)
  T delta_o_prev = 0;  // delta_o at the last step (radius growth, (37))
  T eps_prev = 0;      // this side's Christoffersen term at the last step ((37)-(38))
  // The plastic shape of the last evaluation that computed one and the (delta_max, R) it was
  // computed for (shape_R = 0: none; R > 0). Below delta_max the ellipse of delta_max is fixed,
  // so while neither moves, unloading and reloading take it from here, the same bits, instead of
  // its exp, two square roots and two divisions (the stored delta_p is that shape's).
  // shape_ratio < 0: the ratio was floored; its magnitude is the ratio.
  T shape_delta_max = 0, shape_R = 0, shape_A = 0, shape_a_max = 0, shape_ratio = 0;
};

// The ellipse of the fully-plastic regime at (delta_max, R, c_A).
template <class T>
struct MdrPlasticShape {
  T A, B;     // (28)
  T a_max;    // (36)
  T p_Y;      // (16) with delta_max/R (21)
  T ratio;    // r = 1 + delta_R/(A/2), floored (mdr_min_recovery_ratio)
  T delta_p;  // residual overlap delta_max - (A/2) r = delta_max - (A/2 + delta_R)
  bool ratio_floored;
};

// inv_R = 1/R (the caller has it). Uses the precomputed constants of MdrSideConstants.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION MdrPlasticShape<T> mdr_plastic_shape(const MdrSideConstants<T>& c, T delta_max, T R,
                                                                 T inv_R, T c_A) {
  MdrPlasticShape<T> s;
  const T pi = constants<T>::pi;
  s.p_Y = c.Y + c.Y_hard * math::exp(T(-4.4) * delta_max * inv_R);  // (16) with (21)
  // (36). Domain: the radicand is >= delta_Y R > 0 for delta_Y <= delta_max <= R. Past the equator
  // (delta_max > R) the cap radius of the truncated sphere would shrink; the equator value is kept.
  const T xm = math::min(delta_max, R);
  const T a2 = math::max(T(2) * xm * R - xm * xm + c_A * (T(1) / pi), T(1e-12) * R * R);
  s.a_max = math::sqrt(a2);  // a2 > 0 (floor above)
  s.A = c.four_over_E * s.p_Y * s.a_max;
  s.B = T(2) * s.a_max;
  const T half = T(0.5) * s.A;  // delta_1D,max^e
  // (33): depth of the particle centre below the undeformed half-space surface; >= 0 (guard).
  const T zR = math::max(R - (delta_max - half), T(0));
  // (34) with F_max/(pi a_max^2) = p_Y exactly (F_max = E A B pi/8, (32) at depth A/2), divided by
  // A/2 = 2 p_Y a_max/E_eff; with sqrt(a^2+z^2) - z = a^2/(rho + z) (no cancellation) it reduces to
  //   delta_R/(A/2) = a_max (E_eff (nu-1)/(2G) rho - E_eff/(4G) z_R) / (rho (rho + z_R)),
  // rho = sqrt(a_max^2 + z_R^2): p_Y cancels and one division remains. rho >= a_max > 0, z_R >= 0,
  // so the denominator is > 0; both numerator terms are <= 0 (nu < 1): no cancellation.
  const T rho = math::sqrt(a2 + zR * zR);
  const T r = T(1) + s.a_max * (c.r_rho * rho - c.r_z * zR) / (rho * (rho + zR));
  s.ratio_floored = r < mdr_min_recovery_ratio<T>();
  s.ratio = s.ratio_floored ? mdr_min_recovery_ratio<T>() : r;
  s.delta_p = delta_max - half * s.ratio;
  return s;
}

// The shape s stores (valid where s.shape_R == R and s.shape_delta_max == delta_max): A, a_max,
// the ratio and delta_p as mdr_plastic_shape gave them; p_Y is not stored (0 here: only plastic
// loading's stiffness reads it, and that recomputes the shape).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION MdrPlasticShape<T> mdr_stored_shape(const MdrSideState<T>& s) {
  MdrPlasticShape<T> sh;
  sh.A = s.shape_A;
  sh.a_max = s.shape_a_max;
  sh.B = T(2) * s.shape_a_max;  // (28), as mdr_plastic_shape
  sh.p_Y = T(0);
  sh.ratio_floored = s.shape_ratio < T(0);
  sh.ratio = math::fabs(s.shape_ratio);
  sh.delta_p = s.delta_p;
  return sh;
}

template <class T>
KOKKOS_FORCEINLINE_FUNCTION void mdr_store_shape(MdrSideState<T>& s, const MdrPlasticShape<T>& sh, T delta_max, T R) {
  s.shape_delta_max = delta_max;
  s.shape_R = R;
  s.shape_A = sh.A;
  s.shape_a_max = sh.a_max;
  s.shape_ratio = sh.ratio_floored ? -sh.ratio : sh.ratio;
}

// Without inv_R (tests, host tools).
template <class T>
KOKKOS_INLINE_FUNCTION MdrPlasticShape<T> mdr_plastic_shape(const MdrSideConstants<T>& c, T delta_max, T R, T c_A) {
  return mdr_plastic_shape(c, delta_max, R, T(1) / R, c_A);  // R > 0 (host validation)
}

// What one side evaluation produces. No member initialisers: a result exists only as
// mdr_side_force's value-initialised `out` or a copy of one, and without them the evaluation's
// working set (MdrEvaluation, two results per contact) is no longer zero-filled per contact (a
// 584-byte memset call in the MDR pair kernel, 2-4% of a step of the authors' scene).
template <class T>
struct MdrSideResult {
  T F;          // MDR force, positive = compressive
  T A, B;       // current ellipse
  T d1De;       // transformed elastic displacement delta_1D^e
  T a;          // contact half-width in MDR space (adhesive a when stretched)
  T delta_max;  // (19)
  T area;       // contact area (42) with c_A, >= 0
  // dF/d delta of this side at this state (what a pair's balance solve needs, mdr_pair_balance.hpp;
  // 0 where the caller asked for none, mdr_side_force's with_stiffness): 2 E_eff a on the elastic
  // branch and on the fixed ellipse below delta_max (times 1/r there, (35)), d(pi p_Y a_max^2)/d
  // delta on plastic loading (may be < 0 near delta = R); in adhesive peeling an estimate (the edge
  // springs' 2 E_eff a).
  T stiffness;
  bool plastic;
  bool loading;        // delta_o >= the previous delta_o,max (plastic loading test)
  bool ratio_floored;  // guard of (35) active
  int adhesion_state;  // MdrAdhesionState, 0 without adhesion
};

// Evaluates one side and advances its state s (the caller writes s back, or not, e.g. for
// outputs). gamma: the pair's Delta gamma (0: no adhesion); xi of (15); growth = R - R_o (0
// without radius growth); a_fac: the adhesive radius factor of mdr_adhesion.hpp (1: the paper).
//
// delta_max follows the paper's (19), delta_max = delta_o,max + R - R_o, with delta_o,max the
// running maximum of delta_o = delta - (R - R_o), rather than the running maximum of delta
// (Appendix E, the authors' code). The two differ by the last step's growth of R; on the stiff
// unloading branch that one-increment lag made the curve depend on the step (0.75% change on
// halving a 2e-4 R_o step at E/Y = 50); with (19), delta - delta_max = delta_o - delta_o,max does
// not see the lag. Without growth the two definitions coincide.
//
// Hot path (per side, only the arithmetic of the current regime): the elastic regime is
// one asin and two sqrt (ellipse force and width); plastic loading (delta at delta_max, the
// common compaction step) is d = A/2 exactly, where (30) is E A B pi/8 and the width B/2, so it
// costs one exp and two sqrt and no inverse trigonometric function; unloading adds the asin.
//
// with_stiffness = false leaves MdrSideResult::stiffness 0: callers that do not solve for the pair
// split (the geometric split, the bulk response, walls, the equal-pair split of one material) then
// skip its two divisions per side; every other result is the same bits.
template <bool Plasticity, bool Adhesion, class T>
KOKKOS_FORCEINLINE_FUNCTION MdrSideResult<T> mdr_side_force(const MdrSideConstants<T>& c, T gamma, T xi, T delta, T R,
                                                            T growth, MdrSideState<T>& s, T a_fac = T(1),
                                                            bool with_stiffness = true) {
  MdrSideResult<T> out{};  // every field zero, then the regime's
  const T pi = constants<T>::pi;
  // (MdrDeltaMax::running_max, the authors' running maximum of delta itself: the model passes
  // growth = 0, and s.delta_o_max then holds the largest delta)
  const T delta_o = delta - growth;
  out.loading = delta_o >= s.delta_o_max;
  // delta - delta_max = delta_o - delta_o,max by (19) (exactly 0 on loading, <= 0 otherwise)
  // (the running maximum is plasticity history; without it delta_max stays R - R_o = 0)
  T below_max = T(0);
  if (Plasticity) {
    if (out.loading)
      s.delta_o_max = delta_o;
    else
      below_max = delta_o - s.delta_o_max;
  }
  const T delta_max = s.delta_o_max + growth;  // (19)
  out.delta_max = delta_max;
  if (Plasticity) {
    // Sharp switch (5.6.5), tested on loading only: unloading lowers the elastic pressure while
    // p_Y(delta_max) stays. x_yield = +inf: never yields.
    if (s.yielded == T(0) && out.loading && delta > c.x_yield * R) {
      s.yielded = T(1);
      s.c_A = c.cA_over_R2 * R * R;  // (43): pi (delta_Y^2 - delta_Y R), delta_Y = x_yield R
    }
  }
  T d1De_per_delta = T(1);  // d delta_1D^e / d delta: 1/r below delta_max ((35)), 1 elastic
  T loading_stiffness = T(0);
  if (Plasticity && s.yielded != T(0)) {
    // the stored shape where (delta_max, R) are those it was computed for (c_A is fixed once
    // yielded), except on loading with the stiffness, which needs p_Y
    const bool stored = s.shape_R == R && s.shape_delta_max == delta_max && !(with_stiffness && out.loading);
    MdrPlasticShape<T> sh;
    if (stored) {
      sh = mdr_stored_shape(s);
    } else {
      sh = mdr_plastic_shape(c, delta_max, R, T(1) / R, s.c_A);  // R > 0
      mdr_store_shape(s, sh, delta_max, R);
    }
    out.plastic = true;
    if (with_stiffness) d1De_per_delta = T(1) / sh.ratio;  // ratio >= mdr_min_recovery_ratio > 0
    if (with_stiffness && out.loading) {
      // plastic loading: F = pi p_Y a_max^2 ((30) at d = A/2 with (28)); p_Y' = -4.4/R (p_Y - Y) by
      // (16)+(21), (a_max^2)' = 2 (R - delta) up to the equator ((36))
      loading_stiffness =
          pi * (T(2) * (R - math::min(delta_max, R)) * sh.p_Y - T(4.4) * (sh.p_Y - c.Y) * sh.a_max * sh.a_max / R);
    }
    out.A = sh.A;
    out.B = sh.B;
    // (35) rewritten as A/2 + (delta - delta_max)/r: the same value, without 0/0 at r -> 0;
    // ratio >= mdr_min_recovery_ratio > 0. On loading exactly A/2.
    out.d1De = out.loading ? T(0.5) * sh.A : T(0.5) * sh.A + below_max / sh.ratio;
    out.ratio_floored = sh.ratio_floored;
    s.delta_p = sh.delta_p;
    // (42), plastic branch, with the current delta
    out.area = math::max(pi * (T(2) * delta * R - delta * delta) + s.c_A, T(0));
  } else {
    out.A = T(4) * R;
    out.B = T(2) * R;
    out.d1De = delta;
    out.area = math::max(pi * delta * R, T(0));  // (42), elastic branch
  }
  if (Adhesion && gamma > T(0)) {
    const MdrAdhesiveForce<T> af = mdr_adhesive_force(c.E_eff, gamma, xi, out.A, out.B, out.d1De, s.a_adh, a_fac);
    out.F = af.F;
    out.a = af.a;
    out.adhesion_state = af.state;
    s.a_adh = af.a;
  } else {
    out.F = mdr_ellipse_force(c.E_eff, out.A, out.B, out.d1De);
    out.a = mdr_ellipse_contact_radius(out.A, out.B, out.d1De);
    if (Adhesion) s.a_adh = T(0);
  }
  if (with_stiffness)
    out.stiffness = (out.plastic && out.loading) ? loading_stiffness : T(2) * c.E_eff * out.a * d1De_per_delta;
  return out;
}

}  // namespace epac
