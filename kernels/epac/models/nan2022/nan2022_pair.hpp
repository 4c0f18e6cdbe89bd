#pragma once
// Nan et al. 2022 linear elasto-plastic adhesive contact: the per-material-pair constants (POD,
// device) and the size-dependent constants of one contact, derived from them at the contact's
// equivalent radius R* (Nan (4)-(9), (27)-(31), (35)-(37), (52)).
//
// Why per contact: f_ce = 1.5 pi Gamma R* (Nan (5)) and the default k_el = pi R* p_y (Nan (52))
// scale with R*, so in a polydisperse packing every contact has its own constants. The pair table
// keeps only what does not depend on size, with the roots of its R*-free factors taken once per
// pair (Nan2022PairDerived); this header derives the rest.
#include <epac/core/kokkos_compat.hpp>

namespace epac {

// How k_e grows with the maximum overlap after yield (Nan Sec. 3.3). With k_el known, Nan (44)
// and (46) are the same law, and Nan (48) is the same as k_p + (k_el - k_p) sqrt(a_max/a_y)
// (substitute Nan (49)). So the device needs only these two forms.
enum class Nan2022UnloadingLaw : int {
  sqrt_max_overlap = 0,  // k_e = k_el sqrt(a_max / a_y)                  Nan (44) = (46), default
  plastic_offset = 1,    // k_e = k_p + (k_el - k_p) sqrt(a_max / a_y)     Nan (48) with (49)
};

// Maximum pull-off force after yield (Nan Sec. 3.4, Table 4).
enum class Nan2022PullOffLaw : int {
  work_balance = 0,      // Nan (59) with A from Nan (56), default
  effective_radius = 1,  // Nan (64)
  stiffness_power = 2,   // Nan (67): f_cp = f_ce (k_e/k_el)^(3/2)
};

// Everything of one material pair the force law needs that does not depend on R*. POD, so it
// lives in a device View. Built and validated on the host (params/nan2022/nan2022_parameters.hpp).
template <class T>
struct Nan2022PairConstants {
  T E_star;          // E* [Pa] > 0
  T surface_energy;  // Gamma [J/m^2] >= 0; 0 = no adhesion for this pair
  T yield_pressure;  // p_y [Pa] > 0 (softer body); read only when yields != 0
  int yields;        // 0: no yield for this pair (p_y infinite): the plastic branch never opens
  int kel_fixed;     // 0: k_el = kel_value * R* (Nan (52): kel_value = pi p_y); 1: k_el = kel_value [N/m]
  T kel_value;
  int kp_fixed;  // 0: k_p = kp_value * k_el (default kp_value = 1); 1: k_p = kp_value [N/m]
  T kp_value;
  int unloading_law;  // Nan2022UnloadingLaw
  int pull_off_law;   // Nan2022PullOffLaw
  T kt_over_kn;       // 4 G*/E*, Nan (22)
  T damping_ratio;    // gamma of Nan (26) with beta = 1 (from e0)
  T beta_yielded;     // damping factor beta after yield (Nan Sec. 2.3; default 0.1)
  T mu;               // sliding friction coefficient
};

// A pair's constants rounded to T once (Nan2022::create_from_pairs, tests).
template <class T>
KOKKOS_INLINE_FUNCTION Nan2022PairConstants<T> nan2022_pair_constants_in(const Nan2022PairConstants<double>& d) {
  Nan2022PairConstants<T> t;
  t.E_star = T(d.E_star);
  t.surface_energy = T(d.surface_energy);
  t.yield_pressure = T(d.yield_pressure);
  t.yields = d.yields;
  t.kel_fixed = d.kel_fixed;
  t.kel_value = T(d.kel_value);
  t.kp_fixed = d.kp_fixed;
  t.kp_value = T(d.kp_value);
  t.unloading_law = d.unloading_law;
  t.pull_off_law = d.pull_off_law;
  t.kt_over_kn = T(d.kt_over_kn);
  t.damping_ratio = T(d.damping_ratio);
  t.beta_yielded = T(d.beta_yielded);
  t.mu = T(d.mu);
  return t;
}

// The size-dependent constants of one contact.
template <class T>
struct Nan2022ContactConstants {
  T f_ce;        // pull-off force before yield, 1.5 pi Gamma R*            Nan (5)
  T f_0;         // force jump at first contact, 8/9 f_ce                    Nan (4)
  T k_el;        // loading stiffness before yield (lower limit of k_e)
  T k_p;         // plastic loading stiffness (<= k_el, see below)
  T f_y;         // yield force                                               Nan (28); 0 if no yield
  T alpha_0;     // zero-force overlap before yield, f_0/k_el                 Nan (6)
  T alpha_y;     // yield overlap alpha_0 + f_y/k_el                          Nan (7), (29); = alpha_0 if no yield
  T el_over_cl;  // k_el/k_cl = k_e/k_c, >= 0 (0 only in the clamped case below)
  T A;           // coefficient of the pull-off quadratic                     Nan (56)
  bool yields;
};

namespace nan2022_detail {
// k_el/k_cl from Nan (35)-(37) and Appendix A. The text's (38)-(39) print this ratio upside down
// (k_cl/k_el); solving (35) W_JKR = (56/162) f_ce^2/k_cl + (17/162) f_ce^2/k_el for k_cl gives
//   k_el/k_cl = W_JKR k_el / ((56/162) f_ce^2) - 17/56
// and with W_JKR = 7.09 (Gamma^5 R*^4 / E*^2)^(1/3) (Nan (37)) and f_ce = 1.5 pi Gamma R*:
//   k_el/k_cl = c k_el / (Gamma^(1/3) E*^(2/3) R*^(2/3)) - 17/56,   c = 7.09 / ((56/162) (1.5 pi)^2)
// = 0.9236... (the paper's 0.92), 17/56 = 0.3036 (the paper's 0.3). (A1) and (A2) also print
// k_cl where k_el belongs in the 17/162 and 64/162 terms.
template <class T>
KOKKOS_INLINE_FUNCTION constexpr T jkr_work_coefficient() {
  return T(7.09);
}
template <class T>
KOKKOS_INLINE_FUNCTION T cohesive_ratio_coefficient() {
  const T pi = constants<T>::pi;
  return jkr_work_coefficient<T>() / (T(56) / T(162) * T(2.25) * pi * pi);
}
}  // namespace nan2022_detail

// The R*-independent factors of a pair's contact constants, derived once per pair (the model
// keeps them beside the pair table) so that a contact needs neither a square root nor a cube root
// on its common branches (loading, elastic unloading):
//   f_y        = f_y_coef R*^2            (k_el = kel_value R*, Nan (52))
//              = f_y_coef R*^2 / sqrt(R*)  (fixed k_el)
//   k_el/k_cl  = cohesive_coef k_el / cbrt(R*^2) - 17/56   (only needed on the adhesive branches)
//   with k_el = kel_value R* also, division-free:
//   alpha_0    = alpha_0_prop             (f_0 / k_el, R*-free)
//   alpha_y    = alpha_0_prop + alpha_y_slope R*
template <class T>
struct Nan2022PairDerived {
  T f_y_coef = 0;       // 0 when the pair does not yield
  T cohesive_coef = 0;  // 0 when Gamma = 0
  T alpha_0_prop = 0;   // read only when kel_fixed == 0
  T alpha_y_slope = 0;  // read only when kel_fixed == 0 and the pair yields
  T kt_root = 0;        // sqrt(kt_over_kn), set by the model's table (one square root for both dampings)
};

// Domains: E* > 0, p_y > 0 when yields, kel_value > 0, Gamma >= 0 (host-validated).
template <class T>
KOKKOS_INLINE_FUNCTION Nan2022PairDerived<T> nan2022_pair_derived(const Nan2022PairConstants<T>& p) {
  const T pi = constants<T>::pi;
  Nan2022PairDerived<T> d;
  if (p.yields) {
    // Nan (28) with (30): f_y = f_y0 sqrt(6/5 k_el / (pi R* p_y)), f_y0 = pi^3 R*^2 p_y s^2 / 6 with
    // s = p_y/E* (Nan (27) rewritten so that no intermediate overflows in float: E*^4 would for
    // E* > 1e9 Pa). With k_el = kel_value R* the root is R*-free; with a fixed k_el it is
    // sqrt(6/5 kel_value/(pi p_y)) / sqrt(R*). sqrt argument > 0 (kel_value, p_y > 0).
    const T s = p.yield_pressure / p.E_star;
    d.f_y_coef = pi * pi * pi * p.yield_pressure * s * s / T(6) *
                 math::sqrt(T(6) / T(5) * p.kel_value / (pi * p.yield_pressure));
  }
  if (!p.kel_fixed) {
    // f_0 / k_el = (8/9) 1.5 pi Gamma R* / (kel_value R*); f_y / k_el = f_y_coef R* / kel_value
    d.alpha_0_prop = T(8) / T(9) * (T(1.5) * pi * p.surface_energy) / p.kel_value;  // kel_value > 0
    d.alpha_y_slope = d.f_y_coef / p.kel_value;
  }
  if (p.surface_energy > T(0)) {
    // cbrt arguments Gamma > 0 and E*^2 > 0 (E*^2 <= 1e26 Pa^2 even in float for E* <= 1e13).
    d.cohesive_coef = nan2022_detail::cohesive_ratio_coefficient<T>() /
                      (math::cbrt(p.surface_energy) * math::cbrt(p.E_star * p.E_star));
  }
  return d;
}

// The contact's constants at equivalent radius R_star, except the cohesive ratio and A
// (nan2022_cohesive_constants below), which only the adhesive branches read.
// Domains: R_star > 0, E* > 0, k_el > 0, p_y > 0 (host-validated; R_star > 0 in every contact).
// Adhesion / Plasticity are the compile-time effects: off means Gamma = 0 / no yield, at no cost.
template <class T, bool Adhesion = true, bool Plasticity = true>
KOKKOS_FORCEINLINE_FUNCTION Nan2022ContactConstants<T> nan2022_contact_base(const Nan2022PairConstants<T>& p,
                                                                            const Nan2022PairDerived<T>& d, T R_star) {
  const T pi = constants<T>::pi;
  Nan2022ContactConstants<T> c;
  const T gamma = Adhesion ? p.surface_energy : T(0);
  c.f_ce = T(1.5) * pi * gamma * R_star;
  c.f_0 = T(8) / T(9) * c.f_ce;
  c.k_el = p.kel_fixed ? p.kel_value : p.kel_value * R_star;
  // k_el > 0; with k_el = kel_value R* the ratios are per pair (Nan2022PairDerived)
  c.alpha_0 = p.kel_fixed ? c.f_0 / c.k_el : (Adhesion ? d.alpha_0_prop : T(0));
  c.yields = Plasticity && p.yields != 0;
  if (c.yields) {
    const T r2 = d.f_y_coef * R_star * R_star;
    c.f_y = p.kel_fixed ? r2 / math::sqrt(R_star) : r2;  // R_star > 0
    c.alpha_y = p.kel_fixed ? c.alpha_0 + c.f_y / c.k_el : c.alpha_0 + d.alpha_y_slope * R_star;
    const T kp = p.kp_fixed ? p.kp_value : p.kp_value * c.k_el;
    // k_p <= k_el keeps k_e >= k_p on every unloading line (Nan's own convention for Fig. 7,
    // k_p = min(k_p, k_e)); otherwise the unloading line would be softer than the loading line
    // and Nan (20) would send unloading back down the plastic line.
    c.k_p = math::min(kp, c.k_el);
  } else {
    c.f_y = T(0);
    c.alpha_y = c.alpha_0;
    c.k_p = c.k_el;
  }
  c.el_over_cl = T(0);
  c.A = T(0);
  return c;
}

// Fills c.el_over_cl and c.A (Nan (35)-(39), (56)) for a contact whose base constants are c.
template <class T, bool Adhesion = true>
KOKKOS_INLINE_FUNCTION void nan2022_cohesive_constants(const Nan2022PairDerived<T>& d, T R_star,
                                                       Nan2022ContactConstants<T>& c) {
  if (Adhesion && c.f_ce > T(0)) {
    // cbrt argument R*^2 > 0. A negative ratio means the linear elastic branch alone stores more
    // than W_JKR (CY below ~1e-3 with Nan (52)); there is no room for a cohesive branch, so it is
    // clamped to zero length (k_c -> infinity). The host report flags this case
    // (Nan2022PairReport::cohesive_ratio_clamped).
    c.el_over_cl = math::max(d.cohesive_coef * c.k_el / math::cbrt(R_star * R_star) - T(17) / T(56), T(0));
    c.A = (T(16) / T(27)) / (T(56) / T(162) * c.el_over_cl + T(17) / T(162));  // denominator >= 17/162
  } else {
    // Gamma = 0: k_cl ~ Gamma^(1/3) -> 0 but the cohesive branch length (4/9) f_cp/k_c ~
    // Gamma^(1/3) -> 0 too; f_cp = f_ce = 0 makes every adhesive term vanish, so neither the
    // ratio nor A is used. Set to 0 rather than the infinite limit.
    c.el_over_cl = T(0);
    c.A = T(0);
  }
}

// nan2022_cohesive_constants as the deferred step of nan2022_normal_step (a functor: no lambda in
// device code).
template <class T, bool Adhesion>
struct Nan2022FillCohesive {
  Nan2022PairDerived<T> d;
  T R_star;
  KOKKOS_INLINE_FUNCTION void operator()(Nan2022ContactConstants<T>& c) const {
    nan2022_cohesive_constants<T, Adhesion>(d, R_star, c);
  }
};

// Every constant of the contact at equivalent radius R_star (host reports, tests, calibration;
// the model evaluates the cohesive part only on the branches that need it).
template <class T, bool Adhesion = true, bool Plasticity = true>
KOKKOS_INLINE_FUNCTION Nan2022ContactConstants<T> nan2022_contact_constants(const Nan2022PairConstants<T>& p,
                                                                            T R_star) {
  const Nan2022PairDerived<T> d = nan2022_pair_derived(p);
  Nan2022ContactConstants<T> c = nan2022_contact_base<T, Adhesion, Plasticity>(p, d, R_star);
  nan2022_cohesive_constants<T, Adhesion>(d, R_star, c);
  return c;
}

}  // namespace epac
