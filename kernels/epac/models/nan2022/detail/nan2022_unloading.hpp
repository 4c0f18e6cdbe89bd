#pragma once
// The unloading line of a contact that has been loaded to alpha_max: its stiffness k_e, the
// zero-force overlap alpha_p, the maximum pull-off force f_cp and the critical overlaps
// alpha_c0 (re-contact), alpha_cp (pull-off) and alpha_jp (detachment), Nan (10)-(16), (46)/(48),
// (59)/(64)/(67). The general forms reduce to the unyielded case (alpha_max = alpha_y:
// k_e = k_el, alpha_p = alpha_0, f_cp = f_ce, alpha_c0 = 0, alpha_cp = alpha_ce, alpha_jp = alpha_je).
#include <epac/models/nan2022/nan2022_pair.hpp>

namespace epac {

template <class T>
struct Nan2022Unloading {
  T alpha_max;  // max(history alpha_max, alpha_y), Nan (10)
  T k_e;        // unloading stiffness
  T k_c;        // cohesive stiffness, k_e / (k_el/k_cl) (k_e in the clamped zero-length case)
  T alpha_p;    // zero force on the unloading line, Nan (16)
  T f_cp;       // maximum pull-off force (>= 0)
  T alpha_c0;   // re-contact overlap, force -8/9 f_cp, Nan (12)
  T alpha_cp;   // pull-off overlap, force -f_cp, Nan (13)
  T alpha_jp;   // detachment overlap, force -5/9 f_cp, Nan (14)
};

// Maximum pull-off force after yield (k_e > k_el or alpha_p > alpha_0).
template <class T>
KOKKOS_INLINE_FUNCTION T nan2022_pull_off_force(const Nan2022ContactConstants<T>& c, T alpha_max, T k_e, T alpha_p,
                                                int law) {
  if (law == static_cast<int>(Nan2022PullOffLaw::effective_radius)) {
    // Nan (64); denominator >= f_y > 0 (only called after yield, so yields and f_y > 0)
    const T d = alpha_max - c.alpha_y;
    return c.f_ce * (c.f_y + k_e * d) / (c.f_y + c.k_p * d);
  }
  if (law == static_cast<int>(Nan2022PullOffLaw::stiffness_power)) {
    const T r = k_e / c.k_el;  // Nan (67), k_el > 0
    return c.f_ce * r * math::sqrt(r);
  }
  // Nan (59), multiplied through by f_ce so that Gamma = 0 needs no division by alpha_0 = 0:
  //   f_cp^2 + A f_ce f_cp - k_e (9/8 A alpha_p f_ce + f_ce^2/k_el) = 0   (alpha_0 = 8/9 f_ce/k_el)
  // The constant term is <= 0 (alpha_p >= alpha_0 >= 0), so the discriminant is >= A^2 f_ce^2 and
  // the positive root is the physical one; sqrt_nonneg only absorbs round-off.
  const T b = c.A * c.f_ce;
  const T q = k_e * (T(9) / T(8) * c.A * alpha_p * c.f_ce + c.f_ce * c.f_ce / c.k_el);
  return T(0.5) * (-b + math::sqrt_nonneg(b * b + T(4) * q));
}

// The contact has not yielded: the unloading line is the loading line (k_el, alpha_0, f_ce).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION bool nan2022_unyielded(const Nan2022ContactConstants<T>& c, T alpha_max) {
  return !c.yields || !(alpha_max > c.alpha_y);
}

// The elastic unloading line alone (alpha_max, k_e, alpha_p) for a history alpha_max (0 = never
// yielded): all that the elastic branch at positive force needs (nan2022_normal_step).
template <class T>
KOKKOS_INLINE_FUNCTION void nan2022_unloading_line(const Nan2022ContactConstants<T>& c, T alpha_max_history,
                                                   int unloading_law, Nan2022Unloading<T>& u) {
  u.alpha_max = math::max(alpha_max_history, c.alpha_y);
  if (nan2022_unyielded(c, u.alpha_max)) {
    // Before yield the general forms reduce exactly to these; taking them directly avoids the
    // 0/0 of Nan (64) at alpha_max = alpha_y and sqrt(0/0) when alpha_y = alpha_0 = 0.
    u.k_e = c.k_el;
    u.alpha_p = c.alpha_0;
  } else {
    const T root = math::sqrt(u.alpha_max / c.alpha_y);  // alpha_y >= f_y/k_el > 0 after yield
    u.k_e = unloading_law == static_cast<int>(Nan2022UnloadingLaw::plastic_offset)
                ? c.k_p + (c.k_el - c.k_p) * root  // Nan (48)
                : c.k_el * root;                   // Nan (46)
    // Nan (16); k_e >= k_el > 0 (one division for both terms)
    const T inv_ke = T(1) / u.k_e;
    u.alpha_p = (T(1) - c.k_p * inv_ke) * u.alpha_max + (c.k_p * c.alpha_y - c.f_y) * inv_ke;
  }
}

// The adhesive part of the unloading line (f_cp and the critical overlaps, Nan (12)-(14)), for a
// line from nan2022_unloading_line; c must hold the cohesive constants (nan2022_cohesive_constants).
template <class T>
KOKKOS_INLINE_FUNCTION void nan2022_unloading_adhesion(const Nan2022ContactConstants<T>& c, int pull_off_law,
                                                       Nan2022Unloading<T>& u) {
  const bool unyielded = nan2022_unyielded(c, u.alpha_max);
  u.f_cp = unyielded ? c.f_ce : nan2022_pull_off_force(c, u.alpha_max, u.k_e, u.alpha_p, pull_off_law);
  const T fk = u.f_cp / u.k_e;
  // Nan (12); before yield alpha_0 - (8/9) f_ce/k_el is 0 exactly (Fig. 2(a): first contact at
  // alpha = 0), whatever the rounding of alpha_0 (a per-pair ratio, nan2022_pair.hpp)
  u.alpha_c0 = unyielded ? T(0) : u.alpha_p - T(8) / T(9) * fk;
  u.alpha_cp = u.alpha_p - fk;                                 // Nan (13)
  u.alpha_jp = u.alpha_cp - T(4) / T(9) * fk * c.el_over_cl;   // Nan (14), k_c = k_e k_cl/k_el
  u.k_c = c.el_over_cl > T(0) ? u.k_e / c.el_over_cl : u.k_e;  // see nan2022_pair.hpp
}

// The unloading line for a history alpha_max (0 = never yielded).
template <class T>
KOKKOS_INLINE_FUNCTION Nan2022Unloading<T> nan2022_unloading(const Nan2022ContactConstants<T>& c, T alpha_max_history,
                                                             int unloading_law, int pull_off_law) {
  Nan2022Unloading<T> u;
  nan2022_unloading_line(c, alpha_max_history, unloading_law, u);
  nan2022_unloading_adhesion(c, pull_off_law, u);
  return u;
}

}  // namespace epac
