// nan2022 in the driver (Nan et al. 2022 linear elasto-plastic adhesive model,
// kernels/epac/models/nan2022/): factory, dispatch and scene check.
// [model] keys: the fields of Nan2022Options (params/nan2022/nan2022_parameters.hpp):
// yield_pressure_from, strain_rate_Y/V_i/V_0, k_el_from, stiffness_pressure, k_el, k_e0,
// alpha_max0, reference_radius, k_p_ratio, k_p, unloading_law, pull_off_law, beta_yielded.
// Effects: adhesion (surface_energy > 0), plasticity (finite yield_stress), damping, friction.
#include "driver/dispatch.hpp"
#include "driver/model_factory.hpp"
#include "driver/model_registry.hpp"
#include "driver/models/meeting_pairs.hpp"
#include "driver/models/nan2022_options.hpp"

#include <epac/models/nan2022/nan2022.hpp>

#include <cmath>

namespace epac {
namespace driver {
Nan2022Options nan2022_options(const Scene& s) {
  const auto& p = s.model.params;
  Nan2022Options o;
  o.yield_pressure_from = static_cast<Nan2022YieldPressureFrom>(choice_of(s, "yield_pressure_from"));
  o.strain_rate_Y = p.at("strain_rate_Y");
  o.strain_rate_V_i = p.at("strain_rate_V_i");
  o.strain_rate_V_0 = p.at("strain_rate_V_0");
  o.k_el_from = static_cast<Nan2022ElasticStiffnessFrom>(choice_of(s, "k_el_from"));
  o.stiffness_pressure = p.at("stiffness_pressure");
  o.k_el = p.at("k_el");
  o.k_e0 = p.at("k_e0");
  o.alpha_max0 = p.at("alpha_max0");
  o.reference_radius = p.at("reference_radius");
  o.k_p_ratio = p.at("k_p_ratio");
  o.k_p = p.at("k_p");
  o.unloading_law = static_cast<Nan2022UnloadingLaw>(choice_of(s, "unloading_law"));
  o.pull_off_law = static_cast<Nan2022PullOffLaw>(choice_of(s, "pull_off_law"));
  o.beta_yielded = p.at("beta_yielded");
  return o;
}

namespace {

template <class T, unsigned Bits, class Device>
struct Nan2022Factory : ModelFactoryBase<Nan2022<T, Effects<Bits>, Device>> {
  using model_type = Nan2022<T, Effects<Bits>, Device>;
  static model_type create(const Scene& s) { return model_type::create(s.materials, nan2022_options(s)); }
};

// Largest detachment separation -alpha_jp (Nan (14)) of a pair at R*, over the plastic histories
// alpha_max in [alpha_y, R*/2] (after yield alpha_jp moves with alpha_max: the unloading line
// shifts by alpha_p while f_cp/k_e changes), sampled; 0 if the pair never separates at a gap.
double nan2022_pair_range(const Nan2022PairConstants<double>& p, double R_star, bool plasticity) {
  const Nan2022ContactConstants<double> c = plasticity ? nan2022_contact_constants<double, true, true>(p, R_star)
                                                       : nan2022_contact_constants<double, true, false>(p, R_star);
  double range = 0.0;
  const Nan2022Unloading<double> u0 = nan2022_unloading(c, 0.0, p.unloading_law, p.pull_off_law);
  range = std::max(range, -u0.alpha_jp);
  if (c.yields) {
    const double lo = std::max(c.alpha_y, 1e-12 * R_star), hi = 0.5 * R_star;
    const int n = 400;
    for (int k = 0; k <= n && lo < hi; ++k) {
      const double am = lo * std::pow(hi / lo, double(k) / n);
      const Nan2022Unloading<double> u = nan2022_unloading(c, am, p.unloading_law, p.pull_off_law);
      range = std::max(range, -u.alpha_jp);
    }
  }
  return range;
}

}  // namespace

RunSummary run_nan2022(const Scene& s, const RunOptions& o) {
  return dispatch_run<Nan2022Factory, kAdhesion | kPlasticity | kFriction | kDamping | kRolling>(s, o);
}

// Validates the options against every pair that can meet (nan2022_pair_constants throws naming
// the pair and the key, e.g. k_el_from = yield_pressure for a pair that does not yield), and
// returns the adhesive range: the largest -alpha_jp over those pairs and their R* (sampled over
// R* between the smallest and largest of the pair, and over alpha_max after yield).
double nan2022_scene_check(const Scene& s) {
  const Nan2022Options o = nan2022_options(s);
  const bool adhesion = (s.model.effects & kAdhesion) != 0u;
  const bool plasticity = (s.model.effects & kPlasticity) != 0u;
  double range = 0.0;
  for (const MeetingPair& mp : meeting_pairs(s)) {
    const Material& A = s.materials[mp.a];
    const Material& B = s.materials[mp.b];
    if (A.rigid && B.rigid) continue;
    const Nan2022PairConstants<double> p = nan2022_pair_constants(A, B, o);
    if (!adhesion || !(p.surface_energy > 0.0)) continue;
    const int n = 16;
    for (int k = 0; k <= n; ++k) {
      const double R = mp.R_star_min * std::pow(mp.R_star_max / mp.R_star_min, double(k) / n);
      range = std::max(range, nan2022_pair_range(p, R, plasticity));
    }
  }
  return range;
}

}  // namespace driver
}  // namespace epac
