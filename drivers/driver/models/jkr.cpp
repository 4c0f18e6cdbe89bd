// jkr in the driver (Hertz-JKR, Nan Appendix B, kernels/epac/models/jkr/): factory, dispatch and
// scene check. No [model] keys. Effects: adhesion (surface_energy > 0), damping, friction.
#include "driver/dispatch.hpp"
#include "driver/model_factory.hpp"
#include "driver/model_registry.hpp"
#include "driver/models/meeting_pairs.hpp"

#include <epac/models/jkr/jkr.hpp>

#include <cmath>

namespace epac {
namespace driver {
namespace {

template <class T, unsigned Bits, class Device>
struct JkrFactory : ModelFactoryBase<Jkr<T, Effects<Bits>, Device>> {
  using model_type = Jkr<T, Effects<Bits>, Device>;
  static model_type create(const Scene& s) { return model_type::create(s.materials); }
};

}  // namespace

RunSummary run_jkr(const Scene& s, const RunOptions& o) {
  return dispatch_run<JkrFactory, kAdhesion | kFriction | kDamping | kRolling>(s, o);
}

// Adhesive range: the contact breaks at the critical overlap delta_c = -(3/4) (pi^2 Gamma^2 R* /
// E*^2)^(1/3) (jkr.hpp), largest at the largest R* of each pair.
double jkr_scene_check(const Scene& s) {
  if (!(s.model.effects & kAdhesion)) return 0.0;
  double range = 0.0;
  for (const MeetingPair& mp : meeting_pairs(s)) {
    const Material& A = s.materials[mp.a];
    const Material& B = s.materials[mp.b];
    if (A.rigid && B.rigid) continue;
    const PairProperties pp = pair_properties(A, B);
    if (!(pp.surface_energy > 0.0)) continue;
    const JkrScales<double> sc = jkr_scales(pp.surface_energy, mp.R_star_max, pp.E_star);
    range = std::max(range, -jkr_critical_overlap_ratio<double>() * sc.delta_s);
  }
  return range;
}

}  // namespace driver
}  // namespace epac
