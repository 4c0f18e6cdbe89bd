#pragma once
// The deterministic mode of a whole force pass (docs/design.md section 6), for a host that evaluates a
// pair list and a wall list per step: per-contact force buffers, the lists' incidences, and the
// model's own per-particle sums (MDR radius growth) stored per contact side, through the model's
// optional deterministic hooks (detail::has_deterministic_hooks, models/model_interface.hpp). Use:
//   DeterministicPass<T, Device> det;
//   det.rebuild(p, pairs, walls);                   // after every list rebuild or spatial sort
//   det.begin(model);                               // each pass
//   compute_pair_forces(model, p, pairs, h, dt, sums, out, det.pair_buffer);
//   compute_wall_forces(model, p, w, walls, hw, dt, sums, out, det.wall_buffer);
//   det.end(model, p);                              // forces, torques and model sums, key order
//   model.update_radii();                           // MDR
// Forces, torques and grown radii then have the same bits on any thread count and backend, for
// any order of the lists and either orientation (i, j) or (j, i) of each pair (the pair kernel
// evaluates every pair in the orientation of the smaller global id). `sums` is not touched.
#include <epac/compute/contact_side_sums.hpp>
#include <epac/compute/deterministic_reduce.hpp>
#include <epac/compute/history_remap.hpp>
#include <epac/models/model_interface.hpp>

namespace epac {

template <class T, class Device>
struct DeterministicPass {
  ContactList<Device> pairs, walls;  // the lists of the last rebuild()
  ContactForceBuffer<T, Device> pair_buffer, wall_buffer;
  ContactIncidence<Device> pair_incidence, wall_incidence;

  // Host: the incidences of the lists (each particle's contacts sorted by key) and room in the
  // buffers (25% headroom on growth). Call after every rebuild of either list.
  void rebuild(const Particles<T, Device>& p, const ContactList<Device>& pair_list,
               const ContactList<Device>& wall_list) {
    pairs = pair_list;
    walls = wall_list;
    pair_incidence = build_incidence(p.n, pairs, pair_contact_keys(p, pairs), true);
    wall_incidence = build_incidence(p.n, walls, wall_contact_keys(p, walls), false);
    auto fit = [](ContactForceBuffer<T, Device>& b, int count) {
      if (count > 0 && static_cast<int>(b.force.extent(0)) < count)
        b = ContactForceBuffer<T, Device>(count + count / 4 + 16);
    };
    fit(pair_buffer, pairs.count);
    fit(wall_buffer, walls.count);
  }

  // Host, before the pass's kernels: clears the model's per-side sums.
  template <class Model>
  void begin(Model& model) const {
    if constexpr (detail::has_deterministic_hooks<Model>::value)
      model.begin_deterministic_pass(pairs.count, walls.count);
  }

  // Host, after the pass's kernels: adds the buffered forces and torques to p.force / p.torque
  // (pair contacts, then wall contacts, each particle in key order) and the model's side sums to
  // its particle sums.
  template <class Model>
  void end(const Model& model, const Particles<T, Device>& p) const {
    if (pairs.count > 0) reduce_contact_forces(p, pair_buffer, pair_incidence);
    if (walls.count > 0) reduce_contact_forces(p, wall_buffer, wall_incidence);
    if constexpr (detail::has_deterministic_hooks<Model>::value)
      model.end_deterministic_pass(p, pairs, pair_incidence, wall_incidence);
  }
};

}  // namespace epac
