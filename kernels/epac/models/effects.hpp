#pragma once
// The physical effects a contact kernel computes, as a compile-time set (docs/design.md section 5).
// A disabled effect compiles to nothing and its history fields are not allocated.
namespace epac {

enum EffectBits : unsigned {
  kAdhesion = 1u << 0,
  kPlasticity = 1u << 1,
  kFriction = 1u << 2,
  kDamping = 1u << 3,
  kRadiusGrowth = 1u << 4,
  kRolling = 1u << 5,       // rolling resistance (models/rolling_resistance.hpp), every law
  kBulkResponse = 1u << 6,  // MDR Part II's bulk response (models/mdr/mdr_bulk_response.hpp), MDR only
  kAllEffects = (1u << 7) - 1u,
};

template <unsigned Bits>
struct Effects {
  static constexpr unsigned bits = Bits;
  static constexpr bool adhesion = (Bits & kAdhesion) != 0;
  static constexpr bool plasticity = (Bits & kPlasticity) != 0;
  static constexpr bool friction = (Bits & kFriction) != 0;
  static constexpr bool damping = (Bits & kDamping) != 0;
  static constexpr bool radius_growth = (Bits & kRadiusGrowth) != 0;
  static constexpr bool rolling = (Bits & kRolling) != 0;
  static constexpr bool bulk_response = (Bits & kBulkResponse) != 0;
};

using AllEffects = Effects<kAllEffects>;

}  // namespace epac
