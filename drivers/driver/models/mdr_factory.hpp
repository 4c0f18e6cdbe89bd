#pragma once
// mdr in the driver: options from [model], the factory (model_factory.hpp's hooks). Used by
// mdr.cpp (Part I's effect sets) and mdr_bulk_response.cpp (the sets with Part II's bulk
// response, compiled in their own unit).
// [model] keys: xi (1 or 3), growth_rule, yield_onset, pair_split, delta_max, damping, friction,
// tangential_stiffness, surface_energy_share, adhesive_radius, release, contact_penalty, psi_b,
// radius_cap, denominator_floor, volume_floor (MdrOptions, mdr_parameters.hpp).
// Per step: before_forces (penalty weights, Part II's mean surface displacement), the force pass
// (each side's growth and bulk terms to the particle sums), after_forces (psi, V_geo, then R grows;
// the contact detector counts the growth against the skin).
#include "driver/model_factory.hpp"
#include "driver/model_registry.hpp"
#include "driver/run_scene.hpp"

#include <epac/models/mdr/mdr_model.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace epac {
namespace driver {

inline MdrOptions mdr_options(const Scene& s) {
  MdrOptions o;
  const double xi = s.model.params.at("xi");
  if (xi != 1.0 && xi != 3.0) {
    std::ostringstream m;
    m << "model.xi = " << xi << " is outside the valid set {1, 3} (MDR (15): 1 displacement control, 3 force control)";
    throw SceneError(m.str());
  }
  o.xi = static_cast<int>(xi);
  o.growth_rule = static_cast<MdrGrowthRule>(choice_of(s, "growth_rule"));
  o.yield_onset = static_cast<MdrYieldOnset>(choice_of(s, "yield_onset"));
  o.pair_split = static_cast<MdrPairSplit>(choice_of(s, "pair_split"));
  o.delta_max = static_cast<MdrDeltaMax>(choice_of(s, "delta_max"));
  o.damping = static_cast<MdrDamping>(choice_of(s, "damping"));
  o.friction = static_cast<MdrFriction>(choice_of(s, "friction"));
  o.surface_energy_share = static_cast<MdrSurfaceEnergyShare>(choice_of(s, "surface_energy_share"));
  o.adhesive_radius = static_cast<MdrAdhesiveRadius>(choice_of(s, "adhesive_radius"));
  o.release = static_cast<MdrRelease>(choice_of(s, "release"));
  o.tangential_stiffness = s.model.params.at("tangential_stiffness");
  o.radius_cap = s.model.params.at("radius_cap");
  o.denominator_floor = s.model.params.at("denominator_floor");
  o.volume_floor = s.model.params.at("volume_floor");
  o.contact_penalty = choice_of(s, "contact_penalty") == 1;
  o.psi_b = s.model.params.at("psi_b");
  o.validate();
  return o;
}

template <class T, unsigned Bits, class Device>
struct MdrFactory : ModelFactoryBase<Mdr<T, Effects<Bits>, Device>> {
  using model_type = Mdr<T, Effects<Bits>, Device>;
  static model_type create(const Scene& s) { return model_type::create(s.materials, mdr_options(s)); }
  static void bind(model_type& m, const Particles<T, Device>& p) { m.bind(p); }
  // [model] contact_penalty = "on": the pair contacts' weights from this step's positions (the
  // per-particle index of the list only after a rebuild); psi_b > 0 (bulk response, Part II): the
  // particles' mean surface displacement, after the weights (it reads the last pass's w A_c).
  template <class Detector>
  static void before_forces(model_type& m, const Particles<T, Device>& p, const Walls<T, Device>& walls,
                            const Detector& det, T) {
    m.compute_contact_penalty(p, det.pairs, -1, det.builds);
    m.compute_mean_surface_displacement(p, det.pairs, det.pair_history, walls, det.walls, det.wall_history);
  }
  // MDR (37)-(39): the apparent radii and volumes from this pass's sums (docs/design.md section 4 step 4).
  static void after_forces(const model_type& m, const Particles<T, Device>&, T) { m.update_radii(); }
  // [run] spatial_sort: the growth state is per particle (R, R_o are the particles' views).
  template <class Permute>
  static void reorder(const model_type& m, const Permute& permute) {
    if (m.bulk.bound()) {  // Part II's per-particle state (its sums are empty between passes)
      permute(m.bulk.acon0);
      permute(m.bulk.psi);
      permute(m.bulk.vgeo);
      permute(m.bulk.ddelta_bar);
    }
    if (!m.growth.bound()) return;
    permute(m.growth.volume);
    permute(m.growth.eps_sum);
    permute(m.growth.numerator);
    permute(m.growth.denominator);
  }
  // contacts.csv columns (Mdr::outputs; pair values are the means of the two sides, side 0 being
  // the particle with the smaller global id; a wall contact has one side).
  // contact_radius: the MDR contact half-width a of the ellipse at the current depth (mean over
  // the sides); area_from_radius = mean pi a^2. On plastic loading pi a^2 = pi a_max^2 equals (42)
  // (by (36)); on unloading (42) keeps the geometric value of the apparent overlap (it is a loading
  // law), while pi a^2 shrinks to 0 where the force does.
  static constexpr int contact_extra_count = 12;
  static std::vector<std::string> contact_extra_names() {
    return {"mdr_force [N]",     "area [m^2]",          "mean_pressure [Pa]", "delta_max [m]",
            "yielded_sides",     "adhesive_radius [m]", "side0_force [N]",    "side1_force [N]",
            "side0_overlap [m]", "side1_overlap [m]",   "contact_radius [m]", "area_from_radius [m^2]"};
  }
  static KOKKOS_INLINE_FUNCTION void contact_extras(const model_type& m, const ContactGeometry<T>& g,
                                                    const HistoryRow<T, Device>& row, T* out) {
    const MdrContactOutput<T> o = m.outputs(g, row);
    out[0] = o.force;
    out[1] = o.area;
    out[2] = o.mean_pressure;
    out[3] = o.delta_max;
    out[4] = T(o.yielded);
    out[5] = o.adhesive_radius;
    out[6] = o.side_force[0];
    out[7] = o.side_force[1];
    out[8] = o.side_overlap[0];
    out[9] = o.side_overlap[1];
    const T inv = T(1) / T(o.sides > 0 ? o.sides : 1);
    out[10] = (o.side_radius[0] + o.side_radius[1]) * inv;
    out[11] = constants<T>::pi * (o.side_radius[0] * o.side_radius[0] + o.side_radius[1] * o.side_radius[1]) * inv;
  }
  // V of MDR (39) (radius growth only; otherwise the file gets 4/3 pi R^3).
  template <class TT, class D>
  static Kokkos::View<T*, Device> particle_volume(const model_type& m) {
    return Effects<Bits>::radius_growth ? m.growth.volume : Kokkos::View<T*, Device>();
  }
  static void report(const model_type& m, RunSummary& sum) {
    if (!Effects<Bits>::radius_growth) return;
    const auto hits = m.guard_hits();
    sum.model_counters.push_back({"mdr_guard_denominator", double(hits[kMdrGuardDenominator])});
    sum.model_counters.push_back({"mdr_guard_radius_cap", double(hits[kMdrGuardRadiusCap])});
    sum.model_counters.push_back({"mdr_guard_volume", double(hits[kMdrGuardVolume])});
    if (Effects<Bits>::bulk_response)
      sum.model_counters.push_back({"mdr_guard_bulk_volume", double(m.bulk_volume_floor_hits())});
    if (m.growth.bound()) {
      const auto R = m.growth.radius;
      const auto R0 = m.growth.radius0;
      double ratio = 1.0;
      Kokkos::parallel_reduce(
          "epac::driver::mdr_max_radius_ratio",
          Kokkos::RangePolicy<typename Device::execution_space>(0, static_cast<int>(R.extent(0))),
          KOKKOS_LAMBDA(int i, double& r) {
            const double q = double(R(i)) / double(R0(i));
            if (q > r) r = q;
          },
          Kokkos::Max<double>(ratio));
      sum.model_counters.push_back({"mdr_max_radius_ratio", ratio});
    }
  }
};

// The run of one effect set (the dispatchers of mdr.cpp and mdr_bulk_response.cpp).
template <class T, unsigned Bits>
RunSummary run_mdr_set(const Scene& s, const RunOptions& o) {
  return run_scene<MdrFactory, T, Bits>(s, o);
}

// Part II's sets (mdr_bulk_response.cpp): plasticity, radius growth and kBulkResponse.
RunSummary run_mdr_bulk(const Scene& s, const RunOptions& o);

}  // namespace driver
}  // namespace epac
