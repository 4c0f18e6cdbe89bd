#pragma once
// The normal force of Nan et al. 2022 as a per-contact state machine, Nan (17)-(20), Sec. 2.1,
// Figs. 1-2. The history is alpha_max (0 until the contact first yields) and the contact state
// cs (0 apart, 1 in contact); every other quantity is derived from them.
//
//   cs = 0 (apart): f = 0. The contact forms when alpha >= alpha_c0: at alpha = 0 with f = -f_0 on
//      first contact (Fig. 2(a)), at alpha_c0 with f = -8/9 f_cp after a detachment that left the
//      particles overlapping (Fig. 2(d)). Once the overlap is negative the pair has separated and
//      the plastic history is dropped (Sec. 2.1: "if a normal overlap is still identified after
//      the detachment ... the plastic deformation is maintained").
//   cs = 1 (in contact), Nan (20):
//      alpha > alpha_max (plastic loading, yield):  f_p = f_y + k_p (alpha - alpha_y)   Nan (18)
//                                                   and alpha_max := alpha           Nan (10)
//      alpha_cp < alpha <= alpha_max:               f_e = k_e (alpha - alpha_p)      Nan (17)
//      alpha_jp <= alpha <= alpha_cp:               f_c = -f_cp + k_c (alpha_cp - alpha)  Nan (19)
//      alpha < alpha_jp:                            detach, cs := 0, f = 0
// Nan (20) picks f_p when f_p <= f_e; for k_p < k_e that is exactly alpha >= alpha_max (the lines
// meet there by Nan (15)). We test the overlap, not the forces, because with the default
// k_p = k_el the two lines coincide before yield and the force test cannot tell loading from
// unloading.
#include <epac/models/nan2022/detail/nan2022_unloading.hpp>

namespace epac {

template <class T>
struct Nan2022NormalState {
  T f = 0;               // normal force, positive repulsive
  T k_n = 0;             // stiffness of the current branch (k_p, k_e or k_c); 0 when apart
  bool active = false;   // the surfaces interact (also at negative overlap down to alpha_jp)
  bool yielded = false;  // the contact has yielded (alpha_max history > 0): damping beta switch
  int branch = 0;        // 0 apart, 1 plastic, 2 elastic, 3 cohesive (for tests and output)
};

namespace nan2022_detail {
// Plastic loading, Nan (18): f_p = f_y + k_p (alpha - alpha_y); alpha_max follows alpha, Nan (10).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION void plastic_loading(const Nan2022ContactConstants<T>& c, T alpha, T& alpha_max,
                                                 Nan2022NormalState<T>& s) {
  alpha_max = alpha;
  s.f = c.f_y + c.k_p * (alpha - c.alpha_y);
  s.k_n = c.k_p;
  s.branch = 1;
}
// For callers whose constants are complete already (tests, host tools).
struct CohesiveConstantsGiven {
  template <class C>
  KOKKOS_INLINE_FUNCTION void operator()(C&) const {}
};
// For callers that keep no unloading line in history: taken anew at every call.
struct NoLineHistory {
  template <class T>
  KOKKOS_INLINE_FUNCTION void line(const Nan2022ContactConstants<T>& c, T alpha_max_history, int unloading_law,
                                   Nan2022Unloading<T>& u) const {
    nan2022_unloading_line(c, alpha_max_history, unloading_law, u);
  }
  KOKKOS_INLINE_FUNCTION void forget() const {}
};
}  // namespace nan2022_detail

// The elastic unloading line (k_e, alpha_p) of the contact's alpha_max, kept in two history fields
// so that a contact unloading or held below alpha_max pays for its square root and divisions
// (Nan (46)/(48), (16)) once, not at every step. k_e = 0 marks it unknown (k_e >= k_el > 0 once
// taken); every change of alpha_max forgets it (both fields 0, as in a new contact's history).
// The values are those nan2022_unloading_line gives for the same inputs, so results do not
// change. It assumes the contact's constants (R*, the pair) stay fixed while it lasts, as they
// do for Nan 2022 (no radius change).
template <class T>
struct Nan2022LineHistory {
  T& k_e;
  T& alpha_p;
  KOKKOS_FORCEINLINE_FUNCTION void line(const Nan2022ContactConstants<T>& c, T alpha_max_history, int unloading_law,
                                        Nan2022Unloading<T>& u) const {
    if (k_e > T(0)) {
      u.alpha_max = math::max(alpha_max_history, c.alpha_y);
      u.k_e = k_e;
      u.alpha_p = alpha_p;
      return;
    }
    nan2022_unloading_line(c, alpha_max_history, unloading_law, u);
    k_e = u.k_e;
    alpha_p = u.alpha_p;
  }
  KOKKOS_INLINE_FUNCTION void forget() const {
    k_e = T(0);
    alpha_p = T(0);
  }
};

// One evaluation at overlap alpha. alpha_max and cs are the contact's history, updated in place.
// Without adhesion the law has no hysteresis (alpha_jp = alpha_cp = alpha_c0 = alpha_p), so a
// model compiled without adhesion stores no cs and passes cs = 0 on every call.
// fill_cohesive(c) completes c with the cohesive constants (a cube root per contact) before the
// first branch that reads them: plastic loading and elastic unloading at positive force (a
// contact in a compressed packing) never call it. Those two branches are tested first; they are
// the branches the full test below would take too (alpha_cp <= alpha_p, as f_cp >= 0), with the
// same values.
// line_history keeps the unloading line between calls (Nan2022LineHistory) or not (the default).
template <class T, bool Plasticity = true, class FillCohesive = nan2022_detail::CohesiveConstantsGiven,
          class LineHistory = nan2022_detail::NoLineHistory>
KOKKOS_FORCEINLINE_FUNCTION Nan2022NormalState<T> nan2022_normal_step(Nan2022ContactConstants<T> c, T alpha,
                                                                      T& alpha_max, T& cs, int unloading_law,
                                                                      int pull_off_law,
                                                                      const FillCohesive& fill_cohesive = {},
                                                                      const LineHistory& line_history = {}) {
  Nan2022NormalState<T> s;
  if (cs == T(0) && alpha < T(0) && alpha_max != T(0)) {  // separated: a new contact next time
    alpha_max = T(0);
    line_history.forget();
  }
  Nan2022Unloading<T> u;
  if (cs != T(0)) {
    s.active = true;
    if (Plasticity && c.yields && alpha > math::max(alpha_max, c.alpha_y)) {
      nan2022_detail::plastic_loading(c, alpha, alpha_max, s);
      line_history.forget();
      s.yielded = true;
      return s;
    }
    line_history.line(c, alpha_max, unloading_law, u);
    if (alpha > u.alpha_p) {
      s.f = u.k_e * (alpha - u.alpha_p);
      s.k_n = u.k_e;
      s.branch = 2;
      s.yielded = alpha_max > T(0);
      return s;
    }
  } else {
    // apart: the line is taken, not kept, so a separated contact's history stays all zero (a new
    // contact); only a contact detached while still overlapping (Fig. 2(d)) needs it here
    nan2022_unloading_line(c, alpha_max, unloading_law, u);
  }
  fill_cohesive(c);
  nan2022_unloading_adhesion(c, pull_off_law, u);
  if (cs == T(0)) {
    if (alpha < u.alpha_c0) return s;  // not (yet) in contact: Fig. 2(a), 2(d)
    cs = T(1);
  }
  s.active = true;
  if (Plasticity && c.yields && alpha > u.alpha_max) {
    nan2022_detail::plastic_loading(c, alpha, alpha_max, s);
    line_history.forget();
  } else if (alpha > u.alpha_cp) {
    s.f = u.k_e * (alpha - u.alpha_p);
    s.k_n = u.k_e;
    s.branch = 2;
  } else if (alpha >= u.alpha_jp) {
    s.f = -u.f_cp + u.k_c * (u.alpha_cp - alpha);
    s.k_n = u.k_c;
    s.branch = 3;
  } else {
    cs = T(0);                                // detachment at alpha_jp with -5/9 f_cp; the plastic history is kept ...
    if (alpha < T(0) && alpha_max != T(0)) {  // ... unless the pair has already separated
      alpha_max = T(0);
      line_history.forget();
    }
    s.active = false;
  }
  s.yielded = alpha_max > T(0);
  return s;
}

}  // namespace epac
