// linear_spring in the driver: factory and dispatch (friction x damping x {double, float}).
// Scene key: [model] stiffness = k_n [N/m].
#include "driver/dispatch.hpp"
#include "driver/model_factory.hpp"
#include "driver/model_registry.hpp"

#include <epac/models/linear_spring.hpp>

namespace epac {
namespace driver {

template <class T, unsigned Bits, class Device>
struct LinearSpringFactory : ModelFactoryBase<LinearSpring<T, Effects<Bits>, Device>> {
  using model_type = LinearSpring<T, Effects<Bits>, Device>;
  static model_type create(const Scene& s) { return model_type::create(s.materials, s.model.params.at("stiffness")); }
};

RunSummary run_linear_spring(const Scene& s, const RunOptions& o) {
  return dispatch_run<LinearSpringFactory, kFriction | kDamping | kRolling>(s, o);
}

}  // namespace driver
}  // namespace epac
