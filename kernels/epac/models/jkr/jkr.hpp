#pragma once
// Hertz-JKR baseline (Nan Appendix B, (B1)-(B5)), with the interface of models/hertz_mindlin.hpp.
//   contact radius a from the overlap by (B3), solved on the stable branch (jkr_contact_radius.hpp)
//   f = 4 E* a^3/(3 R*) - sqrt(8 pi Gamma E*) a^(3/2)          (B1)
//   the contact forms at delta = 0 (f = -8/9 f_ce) and breaks at the critical overlap
//   delta_c = -(3/4) (pi^2 Gamma^2 R* / E*^2)^(1/3) (f = -5/9 f_ce): a hysteresis, so two history
//   fields when adhesion is on, both 0 apart. In contact: the last root y = sqrt(a/a_0) > 0, from
//   which the next step's solve starts (jkr_contact_radius_root: a Newton step or two instead of
//   the closed form's cube roots), and R*^(1/3), the contact's scale a_0 = a0_coeff R*^(2/3),
//   taken once when the contact forms (glibc's cbrt was a fifth of the run). Like Nan 2022's
//   unloading line it assumes R* stays fixed while the contact lasts (no radius change in JKR).
//   Force-controlled pull-off: -1.5 pi Gamma R*.
//   k_n = 2 E* a: the Hertz stiffness at the JKR contact radius. The exact tangent (B2) is
//   infinite at delta_c and negative between delta_c and the pull-off point, unusable for damping
//   and k_t; for f > 0 it is within ~4% of 2 E* a (Nan (B13)). So k_t = (4 G*/E*) k_n = 8 G* a.
//   Damping as Hertz-Mindlin: c from e0 by the exact Hertz relation.
// Without adhesion (compiled out or Gamma = 0 for the pair) the law is Hertz.
#include <epac/models/contact_geometry.hpp>
#include <epac/models/effects.hpp>
#include <epac/models/rolling_resistance.hpp>
#include <epac/core/simd_lanes.hpp>
#include <epac/models/jkr/detail/jkr_contact_radius.hpp>
#include <epac/params/material.hpp>
#include <epac/params/restitution_damping.hpp>
#include <epac/state/contact_history.hpp>

#include <vector>

namespace epac {

template <class T>
struct JkrPair {
  T E_star, surface_energy, kt_over_kn, c_damp, mu;
  T a0_coeff;  // (2 pi Gamma / E*)^(1/3): a_0 = a0_coeff R*^(2/3), (B5), one cube root per contact
  T kt_root;   // sqrt(kt_over_kn): one square root for both dampings (contact_geometry.hpp)
};

template <class T, class Eff = Effects<kAdhesion | kFriction | kDamping>, class Device = DefaultDevice>
struct Jkr {
  using scalar_type = T;
  using effects = Eff;
  using device_type = Device;
  static constexpr const char* name = "jkr";
  static constexpr int root_field = 0;  // if adhesion: 0 apart, else the last radius root y
  static constexpr int r13_field = 1;   // if adhesion: 0 apart, else R*^(1/3) of the contact
  static constexpr int normal_history_size = Eff::adhesion ? 2 : 0;
  static constexpr bool inactive_apart = !Eff::adhesion;  // Hertz without adhesion; adhesion pulls apart
  // the tangential spring's 3 fields, then rolling resistance's 3 (compute/contact_forces.hpp)
  static constexpr int history_size = normal_history_size + (Eff::friction ? 3 : 0) + (Eff::rolling ? 3 : 0);

  Kokkos::View<JkrPair<T>*, Device> pairs;
  int nmat = 0;
  RollingTable<T, Device, Eff::rolling> rolling;  // per material pair; empty unless Eff::rolling
  bool lanes_hold = false;                        // host: one adhesive material (lane_form_applies)

  KOKKOS_FORCEINLINE_FUNCTION NormalForce<T> normal(const ContactGeometry<T>& g,
                                                    const HistoryRow<T, Device>& row) const {
    NormalForce<T> r;
    const JkrPair<T> p = pairs(g.pair);
    const T gamma = Eff::adhesion ? p.surface_energy : T(0);
    T a;
    if (gamma > T(0)) {
      // root_field: 0 apart; in contact, y = sqrt(a/a_0) of the last evaluation (> 0), the warm
      // start of the radius solve (jkr_contact_radius_root)
      const T y_last = row(root_field);
      if (y_last == T(0) && g.delta < T(0)) return r;  // contact forms at delta = 0
      // R* > 0: the cube root is taken on the step the contact forms (history 0) and kept
      const T r13_kept = row(r13_field);
      const T r13 = r13_kept > T(0) ? r13_kept : math::cbrt(g.R_eff);
      const JkrScales<T> s = jkr_scales_from_root(p.a0_coeff, r13, gamma, g.R_eff);
      const T d = g.delta / s.delta_s;                // delta_s > 0
      if (!(d >= jkr_critical_overlap_ratio<T>())) {  // breaks at the critical overlap
        row(root_field) = T(0);
        row(r13_field) = T(0);
        return r;
      }
      const T y = jkr_contact_radius_root(d, y_last);
      row(root_field) = y;
      row(r13_field) = r13;
      a = y * y * s.a0;
      r.f = s.f_ce * jkr_force_ratio_of_root(y);
    } else {
      if (Eff::adhesion) {
        row(root_field) = T(0);
        row(r13_field) = T(0);
      }
      if (g.delta <= T(0)) return r;
      a = math::sqrt(g.R_eff * g.delta);  // Hertz
      r.f = T(4) / T(3) * p.E_star * a * g.delta;
    }
    return contact_force(p, r.f, a);
  }

  // Contacts in lanes (compute/pair_lanes.hpp): the common path of the adhesive law without
  // branches, a contact that stays in contact and whose warm-started root converges
  // (detail/jkr_contact_radius.hpp, jkr_contact_radius_lane); the rest (forming, breaking, a
  // root that needs the closed form) is flagged rare and takes normal(). One material with
  // Gamma > 0.
  static constexpr bool lane_form = Eff::adhesion;
  using lane_constants = JkrPair<T>;
  KOKKOS_FORCEINLINE_FUNCTION lane_constants lane_pair(int k) const { return pairs(k); }
  bool lane_form_applies() const { return lanes_hold; }  // host
  template <int N>
  KOKKOS_FORCEINLINE_FUNCTION static NormalForce<T> normal_lane(const JkrPair<T>& p, T delta, T R_eff,
                                                                LaneHistory<T, N>& hist) {
    static_assert(N == normal_history_size, "epac: Jkr::normal_lane: one lane field per history field");
    const T y_last = hist.v[root_field], r13 = hist.v[r13_field];
    const bool kept = (y_last > T(0)) & (r13 > T(0));  // in contact, root and R*^(1/3) kept
    const JkrScales<T> s = jkr_scales_from_root(p.a0_coeff, r13, p.surface_energy, R_eff);
    const T d = delta / lane_select(kept, s.delta_s, T(1));  // delta_s > 0 where kept
    bool converged = false;
    const T y = jkr_contact_radius_lane(d, y_last, converged);
    hist.rare = !(kept & converged);
    hist.v[root_field] = y;
    return contact_force(p, s.f_ce * jkr_force_ratio_of_root(y), y * y * s.a0);
  }

  // An active contact's NormalForce from the law's force f and contact radius a.
  KOKKOS_FORCEINLINE_FUNCTION static NormalForce<T> contact_force(const JkrPair<T>& p, T f, T a) {
    NormalForce<T> r;
    r.f = f;
    r.active = true;
    r.k_n = T(2) * p.E_star * a;
    if (Eff::damping) {
      r.damping = p.c_damp;
      r.damping_t = p.c_damp;
    }
    if (Eff::friction) {
      r.k_t = p.kt_over_kn * r.k_n;
      r.kt_root_ratio = p.kt_root;
      r.mu = p.mu;
    }
    return r;
  }

  // Host: builds the pair table from validated materials (nmat x nmat, row-major).
  static Jkr create(const std::vector<Material>& materials) {  // host
    Jkr m;
    m.nmat = static_cast<int>(materials.size());
    for (const auto& mat : materials) mat.validate();
    m.pairs = Kokkos::View<JkrPair<T>*, Device>("jkr.pairs", m.nmat * m.nmat);
    auto h = Kokkos::create_mirror_view(m.pairs);
    for (int a = 0; a < m.nmat; ++a)
      for (int b = 0; b < m.nmat; ++b) {
        const Material& A = materials[a];
        const Material& B = materials[b];
        if (A.rigid && B.rigid) {
          h(a * m.nmat + b) = {T(0), T(0), T(0), T(0), T(0), T(0), T(0)};
          continue;
        }
        const PairProperties pp = pair_properties(A, B);
        const std::string from = "the moduli and surface energies of '" + A.name + "' and '" + B.name + "'";  // host
        require_representable<T>("hertz_jkr: E_star", pp.E_star, from);
        require_representable<T>("hertz_jkr: surface_energy", pp.surface_energy, from);
        require_representable<T>("hertz_jkr: kt_over_kn", 4.0 * pp.G_star / pp.E_star, from);
        require_representable<T>("hertz_jkr: cbrt(2 pi gamma / E_star)",
                                 std::cbrt(2.0 * constants<double>::pi * pp.surface_energy / pp.E_star), from);
        h(a * m.nmat + b) = {T(pp.E_star),
                             T(pp.surface_energy),
                             T(4.0 * pp.G_star / pp.E_star),
                             T(hertz_damping_coefficient(pp.restitution)),
                             T(pp.friction),
                             T(std::cbrt(2.0 * constants<double>::pi * pp.surface_energy / pp.E_star)),
                             T(std::sqrt(4.0 * pp.G_star / pp.E_star))};
      }
    Kokkos::deep_copy(m.pairs, h);
    m.rolling = RollingTable<T, Device, Eff::rolling>::create(materials);
    m.lanes_hold = m.nmat == 1 && h(0).surface_energy > T(0);
    return m;
  }
};

}  // namespace epac
