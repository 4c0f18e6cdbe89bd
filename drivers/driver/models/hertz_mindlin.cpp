// hertz_mindlin in the driver: factory and dispatch (friction x damping x {double, float}).
#include "driver/dispatch.hpp"
#include "driver/model_factory.hpp"
#include "driver/model_registry.hpp"

#include <epac/models/hertz_mindlin.hpp>

namespace epac {
namespace driver {

template <class T, unsigned Bits, class Device>
struct HertzMindlinFactory : ModelFactoryBase<HertzMindlin<T, Effects<Bits>, Device>> {
  using model_type = HertzMindlin<T, Effects<Bits>, Device>;
  static model_type create(const Scene& s) { return model_type::create(s.materials); }
};

RunSummary run_hertz_mindlin(const Scene& s, const RunOptions& o) {
  return dispatch_run<HertzMindlinFactory, kFriction | kDamping | kRolling>(s, o);
}

}  // namespace driver
}  // namespace epac
