#pragma once
// Optional per-contact and per-particle outputs (contacts.csv, particles.csv; [run] keys
// contact_output and particle_output). A contact row holds the generic values of the force pass
// (overlap, normal force incl. damping) and the model's extra columns (ModelFactoryBase::
// contact_extra_names / contact_extras; MDR: force, area (42), mean pressure, delta_max, yield,
// adhesive radius). The extras are evaluated right after the force pass, before after_forces
// (MDR: before the radii grow), with the geometry the force pass saw.
#include "driver/outputs.hpp"

#include <epac/compute/contact_forces.hpp>
#include <epac/core/vec3.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace epac {
namespace driver {

// pair_geometry / wall_geometry: kernels/epac/compute/contact_forces.hpp (the kernels' own).

// Collects the contacts of one force pass that interact (overlap > 0 or a nonzero force, e.g.
// adhesion at a gap) with the factory's extra columns.
template <class F, class T, class Device>
ContactRows collect_contacts(const typename F::model_type& model, const Particles<T, Device>& p,
                             const Walls<T, Device>& walls, const ContactList<Device>& pairs,
                             const ContactHistory<T, Device>& pair_history, const ContactList<Device>& wlist,
                             const ContactHistory<T, Device>& wall_history, const ContactOutputs<T, Device>& pair_out,
                             const ContactOutputs<T, Device>& wall_out) {
  using exec = typename Device::execution_space;
  constexpr int ne = F::contact_extra_count;
  ContactRows rows;
  rows.extra_count = ne;
  const int nmat = model.nmat;
  auto gather = [&](const ContactList<Device>& list, const ContactHistory<T, Device>& h,
                    const ContactOutputs<T, Device>& out, bool is_wall) {
    const int n = list.count;
    if (n == 0) return;
    Kokkos::View<T**, Kokkos::LayoutRight, Device> extra("epac::driver::contact_extras", n, ne > 0 ? ne : 1);
    if (ne > 0) {
      const typename F::model_type m = model;
      const Particles<T, Device> pp = p;
      const Walls<T, Device> ww = walls;
      const ContactList<Device> l = list;
      const auto hd = h.data;
      Kokkos::parallel_for(
          "epac::driver::contact_extras", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int k) {
            ContactGeometry<T> g = is_wall ? wall_geometry(pp, ww, l.first(k), l.second(k), nmat)
                                           : pair_geometry(pp, l.first(k), l.second(k), nmat);
            g.contact = k;  // per-contact state of the pass (MDR's contact penalty weights)
            T vals[ne > 0 ? ne : 1];
            F::contact_extras(m, g, HistoryRow<T, Device>{hd, k, 0}, vals);
            for (int c = 0; c < ne; ++c) extra(k, c) = vals[c];
          });
    }
    auto first = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.first);
    auto second = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.second);
    auto ov = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out.overlap);
    auto fn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out.normal_force);
    auto ex = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), extra);
    auto gid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.gid);
    for (int k = 0; k < n; ++k) {
      if (!(ov(k) > T(0)) && fn(k) == T(0)) continue;
      rows.i.push_back(gid(first(k)));
      rows.j.push_back(is_wall ? -1 : gid(second(k)));
      rows.wall.push_back(is_wall ? second(k) : -1);
      rows.overlap.push_back(double(ov(k)));
      rows.force.push_back(double(fn(k)));
      for (int c = 0; c < ne; ++c) rows.extras.push_back(double(ex(k, c)));
    }
  };
  gather(pairs, pair_history, pair_out, false);
  gather(wlist, wall_history, wall_out, true);
  return rows;
}

}  // namespace driver
}  // namespace epac
