#pragma once
// Linear (Hooke) spring-dashpot baseline: f = k_n delta, k_t = (4 G*/E*) k_n (Nan (22)),
// damping c = 2 gamma with gamma from e0 by Nan (26), so a collision rebounds with exactly e0.
#include <epac/models/contact_geometry.hpp>
#include <epac/models/effects.hpp>
#include <epac/models/rolling_resistance.hpp>
#include <epac/params/material.hpp>
#include <epac/params/restitution_damping.hpp>
#include <epac/state/contact_history.hpp>

#include <vector>

namespace epac {

template <class T>
struct LinearSpringPair {
  T k_n, kt_over_kn, c_damp, mu;
  T kt_root;  // sqrt(kt_over_kn): one square root for both dampings (contact_geometry.hpp)
};

template <class T, class Eff = Effects<kFriction | kDamping>, class Device = DefaultDevice>
struct LinearSpring {
  using scalar_type = T;
  using effects = Eff;
  using device_type = Device;
  static constexpr const char* name = "linear_spring";
  static constexpr int normal_history_size = 0;
  static constexpr bool inactive_apart = true;  // normal(): no force where delta <= 0
  // the tangential spring's 3 fields, then rolling resistance's 3 (compute/contact_forces.hpp)
  static constexpr int history_size = normal_history_size + (Eff::friction ? 3 : 0) + (Eff::rolling ? 3 : 0);

  Kokkos::View<LinearSpringPair<T>*, Device> pairs;
  int nmat = 0;
  RollingTable<T, Device, Eff::rolling> rolling;  // per material pair; empty unless Eff::rolling

  KOKKOS_INLINE_FUNCTION NormalForce<T> normal(const ContactGeometry<T>& g, const HistoryRow<T, Device>&) const {
    if (g.delta <= T(0)) return NormalForce<T>();
    return normal_lane(pairs(g.pair), g.delta, g.R_eff);
  }

  // The law of one contact from its pair's constants, without branches (contacts in lanes,
  // compute/pair_lanes.hpp); normal() is its scalar form (the same bits where delta > 0).
  using lane_constants = LinearSpringPair<T>;
  KOKKOS_FORCEINLINE_FUNCTION lane_constants lane_pair(int k) const { return pairs(k); }
  KOKKOS_FORCEINLINE_FUNCTION static NormalForce<T> normal_lane(const LinearSpringPair<T>& p, T delta, T /*R_eff*/) {
    NormalForce<T> r;
    r.active = delta > T(0);
    r.f = p.k_n * delta;
    r.k_n = p.k_n;
    if (Eff::damping) {
      r.damping = p.c_damp;
      r.damping_t = p.c_damp;
    }
    if (Eff::friction) {
      r.k_t = p.kt_over_kn * p.k_n;
      r.kt_root_ratio = p.kt_root;  // lanes require k_t = kt_root^2 k_n (compute/pair_lanes.hpp)
      r.mu = p.mu;
    }
    return r;
  }

  // Host: k_n [N/m] is the same for every pair.
  static LinearSpring create(const std::vector<Material>& materials, double k_n) {  // host
    require_positive("model.stiffness", k_n);
    LinearSpring m;
    m.nmat = static_cast<int>(materials.size());
    for (const auto& mat : materials) mat.validate();
    m.pairs = Kokkos::View<LinearSpringPair<T>*, Device>("linear_spring.pairs", m.nmat * m.nmat);
    auto h = Kokkos::create_mirror_view(m.pairs);
    for (int a = 0; a < m.nmat; ++a)
      for (int b = 0; b < m.nmat; ++b) {
        if (materials[a].rigid && materials[b].rigid) {
          h(a * m.nmat + b) = {T(0), T(0), T(0), T(0), T(0)};
          continue;
        }
        const PairProperties pp = pair_properties(materials[a], materials[b]);
        h(a * m.nmat + b) = {T(k_n), T(4.0 * pp.G_star / pp.E_star), T(2.0 * linear_damping_ratio(pp.restitution)),
                             T(pp.friction), T(std::sqrt(4.0 * pp.G_star / pp.E_star))};
      }
    Kokkos::deep_copy(m.pairs, h);
    m.rolling = RollingTable<T, Device, Eff::rolling>::create(materials);
    return m;
  }
};

}  // namespace epac
