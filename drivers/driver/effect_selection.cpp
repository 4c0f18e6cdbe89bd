#include "driver/effect_selection.hpp"

#include <cmath>
#include <sstream>

namespace epac {
namespace driver {
namespace {
struct Named {
  const char* name;
  unsigned bit;
};
constexpr Named kNames[] = {{"adhesion", kAdhesion},         {"plasticity", kPlasticity},      {"friction", kFriction},
                            {"damping", kDamping},           {"radius_growth", kRadiusGrowth}, {"rolling", kRolling},
                            {"bulk_response", kBulkResponse}};
}  // namespace

std::string effect_names(unsigned bits) {
  std::string s;
  for (const auto& n : kNames)
    if (bits & n.bit) s += (s.empty() ? "" : ", ") + std::string(n.name);
  return s.empty() ? "none" : s;
}

unsigned effect_bit(const std::string& name) {
  for (const auto& n : kNames)
    if (name == n.name) return n.bit;
  return 0;
}

unsigned derive_effects(const std::vector<Material>& mats, const std::vector<int>& particle_mats,
                        const std::vector<int>& wall_mats) {
  unsigned bits = 0;
  auto add_pair = [&](const Material& a, const Material& b) {
    if (a.rigid && b.rigid) return;
    const PairProperties p = pair_properties(a, b);
    if (p.surface_energy > 0) bits |= kAdhesion;
    if (std::isfinite(p.yield_stress)) bits |= kPlasticity;
    if (p.friction > 0) bits |= kFriction;
    if (p.restitution < 1) bits |= kDamping;
    if (p.rolling_friction > 0) bits |= kRolling;
  };
  for (int a : particle_mats) {
    for (int b : particle_mats) add_pair(mats[a], mats[b]);
    for (int w : wall_mats) add_pair(mats[a], mats[w]);
  }
  return bits;
}

std::size_t bytes_per_contact(int fields, std::size_t scalar_size) {
  return static_cast<std::size_t>(fields) * scalar_size + (fields > 0 ? 8u : 0u) + 2 * sizeof(int);
}

std::string bytes_per_contact_text(int fields, std::size_t scalar_size) {
  std::ostringstream s;
  s << fields << " history fields x " << scalar_size << " B";
  if (fields > 0) s << " + key 8 B";
  s << " + indices " << 2 * sizeof(int) << " B = " << bytes_per_contact(fields, scalar_size) << " B per contact";
  return s.str();
}

}  // namespace driver
}  // namespace epac
