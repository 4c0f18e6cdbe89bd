#pragma once
// Hertz normal force with Mindlin-type tangential spring (baseline).
//   f   = (4/3) E* sqrt(R*) delta^(3/2)             (Hertz; MDR (25) is the same law)
//   k_n = df/d(delta) = 2 E* sqrt(R* delta)          (tangent stiffness: damping and k_t)
//   k_t = (4 G*/E*) k_n                               Nan (22)
// Damping F_d = c sqrt(m* k_n) d(delta)/dt with c from e0 by the exact Hertz relation of
// params/restitution_damping.hpp (velocity-independent restitution); the total normal force is
// clamped at zero (no viscous pull near separation).
#include <epac/core/simd_lanes.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/models/effects.hpp>
#include <epac/models/rolling_resistance.hpp>
#include <epac/params/material.hpp>
#include <epac/params/restitution_damping.hpp>
#include <epac/state/contact_history.hpp>

#include <vector>

namespace epac {

template <class T>
struct HertzMindlinPair {
  T E_star, kt_over_kn, c_damp, mu;
  T kt_root;  // sqrt(kt_over_kn): one square root for both dampings (contact_geometry.hpp)
};

template <class T, class Eff = Effects<kFriction | kDamping>, class Device = DefaultDevice>
struct HertzMindlin {
  using scalar_type = T;
  using effects = Eff;
  using device_type = Device;
  static constexpr const char* name = "hertz_mindlin";
  static constexpr int normal_history_size = 0;
  static constexpr bool inactive_apart = true;  // normal(): no force where delta <= 0
  // the tangential spring's 3 fields, then rolling resistance's 3 (compute/contact_forces.hpp)
  static constexpr int history_size = normal_history_size + (Eff::friction ? 3 : 0) + (Eff::rolling ? 3 : 0);

  Kokkos::View<HertzMindlinPair<T>*, Device> pairs;
  int nmat = 0;
  RollingTable<T, Device, Eff::rolling> rolling;  // per material pair; empty unless Eff::rolling

  KOKKOS_INLINE_FUNCTION NormalForce<T> normal(const ContactGeometry<T>& g, const HistoryRow<T, Device>&) const {
    if (g.delta <= T(0)) return NormalForce<T>();
    return normal_lane(pairs(g.pair), g.delta, g.R_eff);
  }

  // The law of one contact from its pair's constants, without branches: contacts in lanes
  // (compute/pair_lanes.hpp) take it for a block of contacts at once; normal() is its scalar
  // form (the same bits where delta > 0). Domain: the root of R* max(delta, 0) >= 0.
  using lane_constants = HertzMindlinPair<T>;
  KOKKOS_FORCEINLINE_FUNCTION lane_constants lane_pair(int k) const { return pairs(k); }
  KOKKOS_FORCEINLINE_FUNCTION static NormalForce<T> normal_lane(const HertzMindlinPair<T>& p, T delta, T R_eff) {
    NormalForce<T> r;
    const T a = math::sqrt(R_eff * lane_max(delta, T(0)));  // Hertz contact radius
    r.active = delta > T(0);
    r.f = T(4) / T(3) * p.E_star * a * delta;
    r.k_n = T(2) * p.E_star * a;
    if (Eff::damping) {
      r.damping = p.c_damp;
      r.damping_t = p.c_damp;
      r.damp_compressive_only = true;
    }
    if (Eff::friction) {
      r.k_t = p.kt_over_kn * r.k_n;
      r.kt_root_ratio = p.kt_root;  // lanes require k_t = kt_root^2 k_n (compute/pair_lanes.hpp)
      r.mu = p.mu;
    }
    return r;
  }

  // Host: builds the pair table from validated materials (nmat x nmat, row-major).
  static HertzMindlin create(const std::vector<Material>& materials) {  // host
    HertzMindlin m;
    m.nmat = static_cast<int>(materials.size());
    for (const auto& mat : materials) mat.validate();
    m.pairs = Kokkos::View<HertzMindlinPair<T>*, Device>("hertz_mindlin.pairs", m.nmat * m.nmat);
    auto h = Kokkos::create_mirror_view(m.pairs);
    for (int a = 0; a < m.nmat; ++a)
      for (int b = 0; b < m.nmat; ++b) {
        const Material& A = materials[a];
        const Material& B = materials[b];
        if (A.rigid && B.rigid) {
          h(a * m.nmat + b) = {T(0), T(0), T(0), T(0), T(0)};
          continue;
        }
        const PairProperties pp = pair_properties(A, B);
        const std::string from = "the moduli of '" + A.name + "' and '" + B.name + "'";  // host
        require_representable<T>("hertz_mindlin: E_star", pp.E_star, from);
        require_representable<T>("hertz_mindlin: kt_over_kn", 4.0 * pp.G_star / pp.E_star, from);
        h(a * m.nmat + b) = {T(pp.E_star), T(4.0 * pp.G_star / pp.E_star), T(hertz_damping_coefficient(pp.restitution)),
                             T(pp.friction), T(std::sqrt(4.0 * pp.G_star / pp.E_star))};
      }
    Kokkos::deep_copy(m.pairs, h);
    m.rolling = RollingTable<T, Device, Eff::rolling>::create(materials);
    return m;
  }
};

}  // namespace epac
