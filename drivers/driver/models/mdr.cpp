// mdr in the driver (Zunker & Kamrin Part I, kernels/epac/models/mdr/): dispatch of Part I's
// effect sets and the scene check; the factory is mdr_factory.hpp, Part II's sets
// mdr_bulk_response.cpp. Effects: adhesion (surface_energy > 0), plasticity (finite
// yield_stress), radius growth (on with plasticity unless [model] effects says otherwise),
// damping, friction, rolling; bulk_response with [model] psi_b > 0.
#include "driver/dispatch.hpp"
#include "driver/models/mdr_factory.hpp"
#include "driver/models/meeting_pairs.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace epac {
namespace driver {
namespace {

// dispatch_run without the sets that have radius growth but no plasticity (growth comes from
// plastic deformation; the scene check refuses them), with rolling but no friction, and with the
// bulk response (mdr_bulk_response.cpp): 36 effect sets x 2 scalar types.
template <class T, unsigned Bits = 0>
RunSummary dispatch_mdr(const Scene& s, const RunOptions& o) {
  if constexpr (Bits > (kAllEffects & ~kBulkResponse)) {
    throw std::logic_error("effects {" + effect_names(s.model.effects) + "} have no compiled instance of model mdr");
  } else if constexpr (((Bits & kRadiusGrowth) != 0u && (Bits & kPlasticity) == 0u) ||
                       ((Bits & kRolling) != 0u && (Bits & kFriction) == 0u) || (Bits & kBulkResponse) != 0u) {
    return dispatch_mdr<T, Bits + 1>(s, o);
  } else {
    if (s.model.effects == Bits) return run_mdr_set<T, Bits>(s, o);
    return dispatch_mdr<T, Bits + 1>(s, o);
  }
}

}  // namespace

RunSummary run_mdr(const Scene& s, const RunOptions& o) {
  if (s.model.effects & kBulkResponse) return run_mdr_bulk(s, o);
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
  // Part II: compiled in with psi_b > 0 (scene.cpp adds the effect), and only then
  const double psi_b = s.model.params.at("psi_b");
  if ((e & kBulkResponse) && !(psi_b > 0.0))
    throw SceneError("model.effects: bulk_response needs model.psi_b > 0 (psi_b = 0: Part I, no bulk response)");
  if (psi_b > 0.0 && !(e & kBulkResponse))
    throw SceneError("model.psi_b = " + std::to_string(psi_b) +
                     " needs the bulk_response effect: add \"bulk_response\" to [model] effects");
  if ((e & kBulkResponse) && !((e & kPlasticity) && (e & kRadiusGrowth)))
    throw SceneError(
        "model.psi_b > 0 (Part II's bulk response) needs plasticity and radius_growth (Part II gates the "
        "growth of MDR (37) by psi; a scene without them is Part I)");
  if ((e & kBulkResponse) && s.run.deterministic)
    throw SceneError(
        "model.psi_b > 0 with run.deterministic = true: Part II's per-particle sums (psi, V_geo, the mean surface "
        "displacement) are not yet in the deterministic mode's ordered sums");
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
