#pragma once
// The common path of Nan 2022's normal law without branches, for contacts in lanes
// (compute/pair_lanes.hpp): a contact in contact (state cs = 1) that loads plastically, Nan (18),
// or is on an elastic unloading line it knows, Nan (17): the line kept in history
// (Nan2022LineHistory) or, before yield, the loading line (k_el, alpha_0). Those are the
// branches a compressed packing takes at nearly every step. Everything else (first contact,
// separation, the cohesive branch, detachment, the first step of unloading after yield) is
// flagged `rare`, and the kernel takes nan2022_normal_step for that contact.
// Each value is the expression nan2022_normal_step and nan2022_contact_base compute on the same
// branch, in the same order, so the results are the same bits (exact selects, core/simd_lanes.hpp).
// Holds where k_el = kel_value R* (Nan (52)) and k_p = kp_value k_el: the pair's ratios are then
// R*-free (Nan2022PairDerived) and the common path needs no root and no division. With a fixed
// k_el or k_p the model keeps the one-contact kernel (Nan2022::lane_form_applies).
#include <epac/core/simd_lanes.hpp>
#include <epac/models/nan2022/nan2022_pair.hpp>

namespace epac {

// One material pair's constants for the lane form (Nan2022::lane_pair).
template <class T>
struct Nan2022LanePair {
  T kel_value;      // k_el = kel_value R*
  T kp_value;       // k_p = min(kp_value k_el, k_el)
  T alpha_0;        // f_0 / k_el, Nan (6)
  T f_y_coef;       // f_y = f_y_coef R*^2, Nan (28)
  T alpha_y_slope;  // alpha_y = alpha_0 + alpha_y_slope R*, Nan (7)
  bool yields;
  T damping_ratio, beta_yielded, kt_over_kn, kt_root, mu;
};

template <class T>
KOKKOS_INLINE_FUNCTION Nan2022LanePair<T> nan2022_lane_pair(const Nan2022PairConstants<T>& p,
                                                            const Nan2022PairDerived<T>& d) {
  return {p.kel_value,    p.kp_value,   d.alpha_0_prop, d.f_y_coef, d.alpha_y_slope, p.yields != 0, p.damping_ratio,
          p.beta_yielded, p.kt_over_kn, d.kt_root,      p.mu};
}

// Whether the lane form holds for a pair (host): Nan (52)'s k_el and a proportional k_p.
template <class T>
bool nan2022_lane_form_holds(const Nan2022PairConstants<T>& p) {  // host
  return p.kel_fixed == 0 && p.kp_fixed == 0;
}

// Flags as T (1 or 0), not bool: with two bools beside two floats g++ 12 keeps the struct in
// memory and does not vectorise the lane loop ("complicated access pattern"; float only).
template <class T>
struct Nan2022LaneState {
  T f, k_n;
  T yielded;  // the damping's beta switch, as Nan2022NormalState::yielded
  T rare;     // not on the common path: nothing here holds, the caller takes the scalar law
};

// alpha: overlap; R: R*; alpha_max, line_k_e, line_alpha_p: the contact's history (0 without
// plasticity), rewritten on the common path; cs: the contact state (kept: the common path never
// changes it). No division, root or log: every operand is finite for finite inputs.
template <class T, bool Plasticity>
KOKKOS_FORCEINLINE_FUNCTION Nan2022LaneState<T> nan2022_normal_lane_state(const Nan2022LanePair<T>& p, T alpha, T R,
                                                                          T& alpha_max, T& line_k_e, T& line_alpha_p,
                                                                          T cs) {
  const bool yields = Plasticity & p.yields;
  const T k_el = p.kel_value * R;
  const T alpha_y = lane_select(yields, p.alpha_0 + p.alpha_y_slope * R, p.alpha_0);
  const T f_y = p.f_y_coef * R * R;  // f_y_coef = 0 where the pair does not yield
  const T k_p = lane_select(yields, lane_min(p.kp_value * k_el, k_el), k_el);
  const T alpha_top = lane_max(alpha_max, alpha_y);  // Nan (10)
  const bool in_contact = cs != T(0);
  const bool plastic = in_contact & yields & (alpha > alpha_top);
  const bool kept = line_k_e > T(0);                        // the line in history
  const bool unyielded = !yields | !(alpha_top > alpha_y);  // nan2022_unyielded: the loading line
  const T k_e = lane_select(kept, line_k_e, k_el);
  const T alpha_p = lane_select(kept, line_alpha_p, p.alpha_0);
  const bool elastic = in_contact & !plastic & (kept | unyielded) & (alpha > alpha_p);
  Nan2022LaneState<T> s;
  s.rare = lane_select(plastic | elastic, T(0), T(1));
  s.f = lane_select(plastic, f_y + k_p * (alpha - alpha_y), k_e * (alpha - alpha_p));  // Nan (18), (17)
  s.k_n = lane_select(plastic, k_p, k_e);
  s.yielded = lane_select(plastic | (alpha_max > T(0)), T(1), T(0));
  alpha_max = lane_select(plastic, alpha, alpha_max);
  line_k_e = lane_select(plastic, T(0), k_e);  // loading forgets the line; unloading keeps it
  line_alpha_p = lane_select(plastic, T(0), alpha_p);
  return s;
}

}  // namespace epac
