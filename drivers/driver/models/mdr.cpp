// mdr in the driver (Zunker & Kamrin Part I, kernels/epac/models/mdr/): factory, dispatch and
// scene check.
// [model] keys: xi (1 or 3), growth_rule, yield_onset, pair_split, delta_max, damping, friction,
// tangential_stiffness, surface_energy_share, adhesive_radius, release, contact_penalty, radius_cap, denominator_floor, volume_floor (MdrOptions, mdr_parameters.hpp). Effects: adhesion (surface_energy > 0),
// plasticity (finite yield_stress), radius growth (on with plasticity unless [model] effects
// says otherwise), damping, friction.
// Per step: the force pass adds each side's growth terms to the particle sums; after_forces
// applies them (R grows; the contact detector counts the growth against the skin).
#include "driver/dispatch.hpp"
#include "driver/model_factory.hpp"
#include "driver/model_registry.hpp"
#include "driver/models/meeting_pairs.hpp"

#include <epac/models/mdr/mdr_model.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace epac {
namespace driver {
namespace {

MdrOptions mdr_options(const Scene& s) {
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
  o.validate();
  return o;
}

template <class T, unsigned Bits, class Device>
struct MdrFactory : ModelFactoryBase<Mdr<T, Effects<Bits>, Device>> {
  using model_type = Mdr<T, Effects<Bits>, Device>;
  static model_type create(const Scene& s) { return model_type::create(s.materials, mdr_options(s)); }
  static void bind(model_type& m, const Particles<T, Device>& p) { m.bind(p); }
  // [model] contact_penalty = "on": the pair contacts' weights from this step's positions (the
  // per-particle index of the list only after a rebuild).
  static void before_forces(model_type& m, const Particles<T, Device>& p, const ContactList<Device>& pairs,
                            std::int64_t builds, T) {
    m.compute_contact_penalty(p, pairs, -1, builds);
  }
  // MDR (37)-(39): the apparent radii and volumes from this pass's sums (docs/design.md section 4 step 4).
  static void after_forces(const model_type& m, const Particles<T, Device>&, T) { m.update_radii(); }
  // [run] spatial_sort: the growth state is per particle (R, R_o are the particles' views).
  template <class Permute>
  static void reorder(const model_type& m, const Permute& permute) {
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

// dispatch_run without the sets that have radius growth but no plasticity (growth comes from
// plastic deformation; the scene check refuses them) and with rolling but no friction: 36 effect
// sets x 2 scalar types.
template <class T, unsigned Bits = 0>
RunSummary dispatch_mdr(const Scene& s, const RunOptions& o) {
  if constexpr (Bits > kAllEffects) {
    throw std::logic_error("effects {" + effect_names(s.model.effects) + "} have no compiled instance of model mdr");
  } else if constexpr (((Bits & kRadiusGrowth) != 0u && (Bits & kPlasticity) == 0u) ||
                       ((Bits & kRolling) != 0u && (Bits & kFriction) == 0u)) {
    return dispatch_mdr<T, Bits + 1>(s, o);
  } else {
    if (s.model.effects == Bits) return run_scene<MdrFactory, T, Bits>(s, o);
    return dispatch_mdr<T, Bits + 1>(s, o);
  }
}

}  // namespace

RunSummary run_mdr(const Scene& s, const RunOptions& o) {
  if (o.precision == "float") return dispatch_mdr<float>(s, o);
  return dispatch_mdr<double>(s, o);
}

// Options, deformable particles, growth only with plasticity; adhesive range.
// Adhesive range: a side stays in contact while its edge springs are stretched by at most
// Delta l(a) = sqrt(2 pi a gamma_s / E_eff), MDR (11), i.e. delta_1D^e >= -Delta l(a). The apparent
// overlap is delta = delta_p + r delta_1D^e (35), with the residual overlap delta_p >= 0 and
// r = 1 + delta_R/(A/2) <= 1 (delta_R of (34) is negative: its numerator is below -a_max^2 p_Y for
// nu < 1/2), so delta >= -Delta l(a). a <= B/2 <= R (elastic B = 2R; plastic B = 2 a_max and
// a_max <= R by (36), c_A <= 0), and R <= radius_cap R_o. A pair separates at the sum of its two
// sides' ranges.
double mdr_scene_check(const Scene& s) {
  const MdrOptions o = mdr_options(s);
  const unsigned e = s.model.effects;
  if ((e & kRadiusGrowth) && !(e & kPlasticity))
    throw SceneError(
        "model.effects: radius_growth needs plasticity for model mdr (the apparent radius grows by "
        "plastic flow, MDR (37))");
  for (int m : particle_materials(s))
    if (s.materials[m].rigid)
      throw SceneError("materials." + s.materials[m].name +
                       " is rigid, but model mdr needs deformable particles "
                       "(each side of an MDR contact is a deformable particle against a rigid flat)");
  if (!(e & kAdhesion)) return 0.0;
  const double pi = 3.14159265358979323846;
  double range = 0.0;
  for (const MeetingPair& mp : meeting_pairs(s)) {
    const Material& A = s.materials[mp.a];
    const Material& B = s.materials[mp.b];
    const PairProperties pp = pair_properties(A, B);
    if (!(pp.surface_energy > 0.0)) continue;
    auto side = [&](const Material& m, double R) {
      const double E_eff = m.youngs_modulus / (1.0 - m.poisson_ratio * m.poisson_ratio);
      const double gamma_s = pp.surface_energy * pp.E_star / E_eff;  // the side's share (mdr_model.hpp)
      const double a_bound = o.radius_cap * R;
      return std::sqrt(2.0 * pi * a_bound * gamma_s / E_eff);
    };
    const double r = side(A, mp.ra_max) + (mp.wall ? 0.0 : side(B, mp.rb_max));
    range = std::max(range, r);
  }
  return range;
}

}  // namespace driver
}  // namespace epac
