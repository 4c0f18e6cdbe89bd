#pragma once
// Runtime-to-compile-time dispatch: (scene effects bits, precision) -> run_scene<Factory, T, Bits>.
// Only the effect sets that are subsets of a model's Supported mask and contain its Required
// bits are instantiated, and rolling resistance only with friction (the scene check refuses it
// alone): hertz_mindlin 6 sets x 2 scalar types.
#include "driver/run_scene.hpp"

#include <stdexcept>

namespace epac {
namespace driver {

template <template <class, unsigned, class> class Factory, unsigned Supported, unsigned Required, class T,
          unsigned Bits = 0>
RunSummary dispatch_effects(const Scene& s, const RunOptions& o) {
  if constexpr (Bits > kAllEffects) {
    throw std::logic_error("effects {" + effect_names(s.model.effects) + "} have no compiled instance of model " +
                           s.model.name + " (supported: " + effect_names(Supported) + ")");
  } else if constexpr ((Bits & ~Supported) != 0u || (Bits & Required) != Required ||
                       ((Bits & kRolling) != 0u && (Bits & kFriction) == 0u)) {
    return dispatch_effects<Factory, Supported, Required, T, Bits + 1>(s, o);
  } else {
    if (s.model.effects == Bits) return run_scene<Factory, T, Bits>(s, o);
    return dispatch_effects<Factory, Supported, Required, T, Bits + 1>(s, o);
  }
}

template <template <class, unsigned, class> class Factory, unsigned Supported, unsigned Required = 0u>
RunSummary dispatch_run(const Scene& s, const RunOptions& o) {
  if (o.precision == "float") return dispatch_effects<Factory, Supported, Required, float>(s, o);
  return dispatch_effects<Factory, Supported, Required, double>(s, o);
}

}  // namespace driver
}  // namespace epac
