#pragma once
// Nan et al. 2022 linear elasto-plastic adhesive contact model, with the interface of
// models/hertz_mindlin.hpp.
//   normal force:  the state machine of nan2022_normal_law.hpp, Nan (3)-(20)
//   k_n:           stiffness of the current branch (k_p, k_e or k_c), Nan Sec. 2.2
//   k_t:           (4 G*/E*) k_n, Nan (22)
//   damping:       F_d = 2 gamma beta sqrt(m* k_n) V_n, Nan (24)-(26), beta = 1 before the contact
//                  yields and beta_yielded (default 0.1) after, Nan Sec. 2.3
// History (only for compiled-in effects): alpha_max and its unloading line k_e, alpha_p
// (plasticity; Nan2022LineHistory), contact state (adhesion).
// An adhesive contact stays `active` at negative overlap down to alpha_jp, so contact detection
// must keep pairs whose gap is up to |alpha_jp| (see nan2022_pair_report: alpha_je).
#include <epac/models/contact_geometry.hpp>
#include <epac/models/effects.hpp>
#include <epac/models/rolling_resistance.hpp>
#include <epac/models/nan2022/detail/nan2022_lane_form.hpp>
#include <epac/models/nan2022/detail/nan2022_normal_law.hpp>
#include <epac/params/nan2022/nan2022_parameters.hpp>
#include <epac/state/contact_history.hpp>

#include <vector>

namespace epac {

template <class T, class Eff = Effects<kAdhesion | kPlasticity | kFriction | kDamping>, class Device = DefaultDevice>
struct Nan2022 {
  using scalar_type = T;
  using effects = Eff;
  using device_type = Device;
  static constexpr const char* name = "nan2022";
  static constexpr int alpha_max_field = 0;                    // if plasticity
  static constexpr int line_k_e_field = 1;                     // if plasticity: Nan2022LineHistory
  static constexpr int line_alpha_p_field = 2;                 // if plasticity
  static constexpr int state_field = Eff::plasticity ? 3 : 0;  // if adhesion
  static constexpr int normal_history_size = (Eff::plasticity ? 3 : 0) + (Eff::adhesion ? 1 : 0);
  // the tangential spring's 3 fields, then rolling resistance's 3 (compute/contact_forces.hpp)
  static constexpr int history_size = normal_history_size + (Eff::friction ? 3 : 0) + (Eff::rolling ? 3 : 0);

  Kokkos::View<Nan2022PairConstants<T>*, Device> pairs;
  Kokkos::View<Nan2022PairDerived<T>*, Device> derived;  // the roots of pairs(k), taken on the host
  int nmat = 0;
  RollingTable<T, Device, Eff::rolling> rolling;  // per material pair; empty unless Eff::rolling
  bool lanes_hold = false;                        // host: one material whose pair has the lane form (lane_form_applies)

  KOKKOS_FORCEINLINE_FUNCTION NormalForce<T> normal(const ContactGeometry<T>& g,
                                                    const HistoryRow<T, Device>& row) const {
    const Nan2022PairConstants<T> p = pairs(g.pair);
    const Nan2022PairDerived<T> d = derived(g.pair);
    const T R = g.R_eff;
    const Nan2022ContactConstants<T> c = nan2022_contact_base<T, Eff::adhesion, Eff::plasticity>(p, d, R);
    T alpha_max = Eff::plasticity ? row(alpha_max_field) : T(0);
    T cs = Eff::adhesion ? row(state_field) : T(0);
    T line_k_e = Eff::plasticity ? row(line_k_e_field) : T(0);
    T line_alpha_p = Eff::plasticity ? row(line_alpha_p_field) : T(0);
    const Nan2022FillCohesive<T, Eff::adhesion> fill_cohesive{d, R};
    const Nan2022NormalState<T> s =
        nan2022_normal_step<T, Eff::plasticity>(c, g.delta, alpha_max, cs, p.unloading_law, p.pull_off_law,
                                                fill_cohesive, Nan2022LineHistory<T>{line_k_e, line_alpha_p});
    if (Eff::plasticity) {
      row(alpha_max_field) = alpha_max;
      row(line_k_e_field) = line_k_e;
      row(line_alpha_p_field) = line_alpha_p;
    }
    if (Eff::adhesion) row(state_field) = cs;
    if (!s.active) return NormalForce<T>();
    return contact_force(s.f, s.k_n, s.yielded ? p.beta_yielded : T(1), p.damping_ratio, p.kt_over_kn, d.kt_root, p.mu);
  }

  // Contacts in lanes (compute/pair_lanes.hpp): the law's common path without branches
  // (detail/nan2022_lane_form.hpp), for the full model's state machine (adhesion compiled in:
  // without it every step takes the detached state's path, which has no common form) and one
  // material with Nan (52)'s k_el. `hist` holds the normal history fields; `hist.rare` sends the
  // contact to normal().
  static constexpr bool lane_form = Eff::adhesion;
  using lane_constants = Nan2022LanePair<T>;
  KOKKOS_FORCEINLINE_FUNCTION lane_constants lane_pair(int k) const { return nan2022_lane_pair(pairs(k), derived(k)); }
  bool lane_form_applies() const { return lanes_hold; }  // host
  template <int N>
  KOKKOS_FORCEINLINE_FUNCTION static NormalForce<T> normal_lane(const lane_constants& p, T delta, T R_eff,
                                                                LaneHistory<T, N>& hist) {
    static_assert(N == normal_history_size, "epac: Nan2022::normal_lane: one lane field per history field");
    T unused[3] = {T(0), T(0), T(0)};  // without plasticity: no alpha_max and no kept line
    T& alpha_max = Eff::plasticity ? hist.v[alpha_max_field] : unused[0];
    T& line_k_e = Eff::plasticity ? hist.v[line_k_e_field] : unused[1];
    T& line_alpha_p = Eff::plasticity ? hist.v[line_alpha_p_field] : unused[2];
    const Nan2022LaneState<T> s = nan2022_normal_lane_state<T, Eff::plasticity>(p, delta, R_eff, alpha_max, line_k_e,
                                                                                line_alpha_p, hist.v[state_field]);
    hist.rare = s.rare != T(0);
    NormalForce<T> r = contact_force(s.f, s.k_n, lane_select(s.yielded != T(0), p.beta_yielded, T(1)), p.damping_ratio,
                                     p.kt_over_kn, p.kt_root, p.mu);
    return r;
  }

  // An active contact's NormalForce from the law's force and stiffness; beta: 1 before the
  // contact yields, beta_yielded after (Nan Sec. 2.3).
  KOKKOS_FORCEINLINE_FUNCTION static NormalForce<T> contact_force(T f, T k_n, T beta, T damping_ratio, T kt_over_kn,
                                                                  T kt_root, T mu) {
    NormalForce<T> r;
    r.active = true;
    r.f = f;
    r.k_n = k_n;
    if (Eff::damping) {
      r.damping = T(2) * damping_ratio * beta;  // Nan (24), (26)
      r.damping_t = r.damping;                  // Nan (25)
    }
    if (Eff::friction) {
      r.k_t = kt_over_kn * r.k_n;
      r.kt_root_ratio = kt_root;
      r.mu = mu;
    }
    return r;
  }

  // Host: a pair table from per-pair constants (nmat x nmat, row-major), each validated.
  static Nan2022 create_from_pairs(int nmat, const std::vector<Nan2022PairConstants<double>>& table) {  // host
    require_range("nan2022 material count", nmat, 1, Bound::closed, 1 << 15, Bound::closed);
    require_range("nan2022 pair table size", static_cast<double>(table.size()), nmat * nmat, Bound::closed, nmat * nmat,
                  Bound::closed);
    Nan2022 m;
    m.nmat = nmat;
    m.pairs = Kokkos::View<Nan2022PairConstants<T>*, Device>("nan2022.pairs", nmat * nmat);
    m.derived = Kokkos::View<Nan2022PairDerived<T>*, Device>("nan2022.derived", nmat * nmat);
    auto h = Kokkos::create_mirror_view(m.pairs);
    auto hd = Kokkos::create_mirror_view(m.derived);
    for (int k = 0; k < nmat * nmat; ++k) {
      const Nan2022PairConstants<double>& d = table[k];
      // a rigid-rigid entry is all zero (never used): skip its validation
      if (d.E_star != 0.0) {
        const std::string name = "nan2022 pair " + std::to_string(k);  // host
        nan2022_validate(d, name);
        const std::string from = "the pair's moduli, surface energies, yield stresses and stiffnesses";  // host
        require_representable<T>(name + ": E_star", d.E_star, from);
        require_representable<T>(name + ": surface_energy", d.surface_energy, from);
        require_representable<T>(name + ": yield_pressure", d.yield_pressure, from);
        require_representable<T>(name + ": k_el value", d.kel_value, from);
        require_representable<T>(name + ": k_p value", d.kp_value, from);
        require_representable<T>(name + ": kt_over_kn", d.kt_over_kn, from);
        // the roots in double, rounded once
        const Nan2022PairDerived<double> dd = nan2022_pair_derived(d);
        require_representable<T>(name + ": yield force coefficient (Nan (28))", dd.f_y_coef, from);
        require_representable<T>(name + ": cohesive ratio coefficient (Nan (38))", dd.cohesive_coef, from);
        hd(k).f_y_coef = T(dd.f_y_coef);
        hd(k).cohesive_coef = T(dd.cohesive_coef);
        require_representable<T>(name + ": zero-force overlap f_0/k_el (Nan (6))", dd.alpha_0_prop, from);
        require_representable<T>(name + ": yield overlap slope f_y/(k_el R*) (Nan (7))", dd.alpha_y_slope, from);
        hd(k).alpha_0_prop = T(dd.alpha_0_prop);
        hd(k).alpha_y_slope = T(dd.alpha_y_slope);
        hd(k).kt_root = T(std::sqrt(d.kt_over_kn));
      }
      h(k) = nan2022_pair_constants_in<T>(d);
    }
    Kokkos::deep_copy(m.pairs, h);
    Kokkos::deep_copy(m.derived, hd);
    m.lanes_hold = nmat == 1 && table[0].E_star != 0.0 && nan2022_lane_form_holds(table[0]);
    return m;
  }

  // Host: the pair table from validated materials with the same options for every pair.
  static Nan2022 create(const std::vector<Material>& materials, const Nan2022Options& opt = {}) {  // host
    const int n = static_cast<int>(materials.size());
    std::vector<Nan2022PairConstants<double>> table(static_cast<std::size_t>(n) * n);  // host
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        if (materials[a].rigid && materials[b].rigid) {
          table[a * n + b] = Nan2022PairConstants<double>{};
          continue;
        }
        table[a * n + b] = nan2022_pair_constants(materials[a], materials[b], opt);
      }
    Nan2022 m = create_from_pairs(n, table);
    m.rolling = RollingTable<T, Device, Eff::rolling>::create(materials);
    return m;
  }
};

}  // namespace epac
