#pragma once
// Shared bits of the stability tests (test_all_laws_stability.cpp, test_fuzz_paths.cpp): test
// materials, a rigid wall, and per law a maker of the model from a material list.
#include <backends.hpp>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/nan2022/nan2022.hpp>

#include <vector>

namespace epac {
namespace test {

constexpr unsigned kAllButGrowth = kAdhesion | kPlasticity | kFriction | kDamping;

// gamma: Delta gamma / (E R)
inline Material stability_material(double E, double Y, double gamma, double R) {
  Material m;
  m.name = "m";
  m.youngs_modulus = E;
  m.poisson_ratio = 0.3;
  m.density = 2500;
  m.restitution = 0.5;
  m.friction = 0.5;
  m.surface_energy = gamma * E * R;
  m.yield_stress = Y;
  return m;
}
inline Material stability_wall() {
  Material m;
  m.name = "wall";
  m.rigid = true;
  return m;
}

// Model makers: make(materials) builds the law with its stability-test effects.
template <class T>
struct MakeHM {
  using M = HertzMindlin<T, Effects<kFriction | kDamping>>;
  static constexpr const char* name = "hertz_mindlin";
  static M make(const std::vector<Material>& m) { return M::create(m); }
};
template <class T>
struct MakeJkr {
  using M = Jkr<T, Effects<kAllButGrowth>>;
  static constexpr const char* name = "hertz_jkr";
  static M make(const std::vector<Material>& m) { return M::create(m); }
};
template <class T>
struct MakeNan {
  using M = Nan2022<T, Effects<kAllButGrowth>>;
  static constexpr const char* name = "nan2022";
  static M make(const std::vector<Material>& m) { return M::create(m); }
};
template <class T>
struct MakeMdr {
  using M = Mdr<T, Effects<kAllButGrowth>>;
  static constexpr const char* name = "mdr";
  static M make(const std::vector<Material>& m) { return M::create(m); }
};
template <class T>
struct MakeMdrGrowth {
  // Part I with every effect: kAllEffects gained Part II's kBulkResponse (opt-in, psi_b > 0, and
  // its own pre-pass per step), which this harness does not drive
  using M = Mdr<T, Effects<kAllEffects & ~kBulkResponse>>;
  static constexpr const char* name = "mdr+growth";
  static M make(const std::vector<Material>& m) { return M::create(m); }
};

}  // namespace test
}  // namespace epac
