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
#include "driver/run_options.hpp"
#include "driver/scene.hpp"

#include <epac/models/contact_geometry.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/particles.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace epac {
namespace driver {

template <class Model>
struct ModelFactoryBase {
  using model_type = Model;
  static constexpr int pair_history_fields = Model::history_size;
  static constexpr int wall_history_fields = Model::history_size;

  // Called once, after the particles exist and before the first force pass (MDR: bind the
  // apparent-radius state to the particles' radii).
  template <class P>
  static void bind(Model&, const P&) {}
  // Called before every force pass (after zero_forces), with the walls, the contact detector (its
  // lists and histories as the pass evaluates them, and `builds`, which changes whenever the
  // lists do) and the step's dt (0 for the first pass).
  template <class P, class W, class Det, class T>
  static void before_forces(const Model&, const P&, const W&, const Det&, T) {}
  // Called after every force pass, before the closing half kick (MDR particle update, design
  // section 4 step 4).
  template <class P, class T>
  static void after_forces(const Model&, const P&, T) {}
  // Called when the driver reorders the particles ([run] spatial_sort, at a rebuild): `permute`
  // reorders a per-particle view in place (permute(view)); a model with per-particle state of
  // its own (MDR's growth state) passes each such view. The particles' views are done already.
  template <class Permute>
  static void reorder(const Model&, const Permute&) {}
  // Model-specific counters for the summary (printed and in summary.json under "model_counters"),
  // e.g. MDR's guard hits. Called once after the last step.
  static void report(const Model&, RunSummary&) {}

  // Extra per-contact columns of contacts.csv ([run] contact_output) and their values for one
  // contact, evaluated read-only right after the force pass (driver/contact_sampling.hpp).
  static constexpr int contact_extra_count = 0;
  static std::vector<std::string> contact_extra_names() { return {}; }
  template <class T, class Device>
  static KOKKOS_INLINE_FUNCTION void contact_extras(const Model&, const ContactGeometry<T>&,
                                                    const HistoryRow<T, Device>&, T*) {}
  // Per-particle volume for particles.csv ([run] particle_output; MDR (39)); empty: the file
  // gets 4/3 pi R^3 of the current radius.
  template <class T, class Device>
  static Kokkos::View<T*, Device> particle_volume(const Model&) {
    return {};
  }
};

}  // namespace driver
}  // namespace epac
