// mdr in the driver, the effect sets with Part II's bulk response ([model] psi_b > 0): plasticity,
// radius growth and kBulkResponse, with or without adhesion, friction (and rolling), damping:
// 12 sets x 2 scalar types, in a unit of their own so that the build compiles them beside mdr.cpp.
#include "driver/models/mdr_factory.hpp"

#include <stdexcept>

namespace epac {
namespace driver {
namespace {

constexpr unsigned kBulkRequired = kPlasticity | kRadiusGrowth | kBulkResponse;

template <class T, unsigned Bits = 0>
RunSummary dispatch_mdr_bulk(const Scene& s, const RunOptions& o) {
  if constexpr (Bits > kAllEffects) {
    throw std::logic_error("effects {" + effect_names(s.model.effects) +
                           "} have no compiled instance of model mdr with bulk_response (it needs plasticity and "
                           "radius_growth)");
  } else if constexpr ((Bits & kBulkRequired) != kBulkRequired ||
                       ((Bits & kRolling) != 0u && (Bits & kFriction) == 0u)) {
    return dispatch_mdr_bulk<T, Bits + 1>(s, o);
  } else {
    if (s.model.effects == Bits) return run_mdr_set<T, Bits>(s, o);
    return dispatch_mdr_bulk<T, Bits + 1>(s, o);
  }
}

}  // namespace

RunSummary run_mdr_bulk(const Scene& s, const RunOptions& o) {
  if (o.precision == "float") return dispatch_mdr_bulk<float>(s, o);
  return dispatch_mdr_bulk<double>(s, o);
}

}  // namespace driver
}  // namespace epac
