#pragma once
// What the driver needs from a model besides the law itself: how to build it from a scene, how
// much history its pair and wall contacts keep, and optional per-step extras. A model factory
// derives from ModelFactoryBase<Model> and defines `static Model create(const Scene&)`;
// it may shadow any member below.
//
// Example (MDR): history differs for pairs (two sides) and walls (one side), and a particle
// update runs after every force pass:
//   template <class T, unsigned Bits, class Device>
//   struct MdrFactory : ModelFactoryBase<Mdr<T, Effects<Bits>, Device>> {
//     using model_type = Mdr<T, Effects<Bits>, Device>;
//     static constexpr int pair_history_fields = 2 * model_type::side_history_size;
//     static constexpr int wall_history_fields = model_type::side_history_size;
//     static model_type create(const Scene& s) { return model_type::create(s.materials, ...); }
//     static void after_forces(const model_type& m, const Particles<T, Device>& p, T dt) {
//       update_apparent_radius(m, p);  // R grows: ContactDetector counts the growth against the skin
//     }
//   };
#include "driver/scene.hpp"

#include <epac/state/particles.hpp>

namespace epac {
namespace driver {

template <class Model>
struct ModelFactoryBase {
  using model_type = Model;
  static constexpr int pair_history_fields = Model::history_size;
  static constexpr int wall_history_fields = Model::history_size;

  // Called before every force pass (after zero_forces), with the step's dt (0 for the first pass).
  template <class P, class T>
  static void before_forces(const Model&, const P&, T) {}
  // Called after every force pass, before the closing half kick (MDR particle update, design
  // section 4 step 4).
  template <class P, class T>
  static void after_forces(const Model&, const P&, T) {}
};

}  // namespace driver
}  // namespace epac
