#pragma once
// Deterministic accumulation (docs/design.md section 6). The contact kernel stores per-contact forces
// in a ContactForceBuffer; here each particle sums its contacts sequentially, in the order of
// the contacts' history keys. The order depends neither on the thread count nor on the order of
// the contact list, so a run gives the same bits on any number of threads.
#include <epac/compute/contact_forces.hpp>

namespace epac {

// For each particle, the contacts it takes part in: entries offsets(i) .. offsets(i+1)-1,
// each 2*k + side (side 0: the contact's first particle, side 1: its second), sorted by key.
template <class Device>
struct ContactIncidence {
  Kokkos::View<int*, Device> offsets;
  Kokkos::View<int*, Device> entries;
};

// Built once per contact-list rebuild. `keys` are the list's history keys (pair_contact_keys or
// wall_contact_keys); `two_sided` is false for wall lists (second = wall index).
template <class Device>
ContactIncidence<Device> build_incidence(int n_particles, const ContactList<Device>& c,
                                         const Kokkos::View<std::uint64_t*, Device>& keys, bool two_sided) {
  using exec = typename Device::execution_space;
  ContactIncidence<Device> inc;
  inc.offsets = Kokkos::View<int*, Device>("incidence.offsets", n_particles + 1);
  auto off = inc.offsets;
  Kokkos::View<int*, Device> fill("incidence.fill", n_particles);
  Kokkos::parallel_for(
      "epac::incidence_count", Kokkos::RangePolicy<exec>(0, c.count), KOKKOS_LAMBDA(int k) {
        Kokkos::atomic_add(&off(c.first(k) + 1), 1);
        if (two_sided) Kokkos::atomic_add(&off(c.second(k) + 1), 1);
      });
  Kokkos::parallel_scan(
      "epac::incidence_scan", Kokkos::RangePolicy<exec>(0, n_particles + 1),
      KOKKOS_LAMBDA(int i, int& sum, bool final) {
        sum += off(i);
        if (final) off(i) = sum;
      });
  int total = 0;
  Kokkos::deep_copy(total, Kokkos::subview(off, n_particles));
  inc.entries = Kokkos::View<int*, Device>("incidence.entries", total);
  auto ent = inc.entries;
  Kokkos::parallel_for(
      "epac::incidence_fill", Kokkos::RangePolicy<exec>(0, c.count), KOKKOS_LAMBDA(int k) {
        const int a = c.first(k);
        ent(off(a) + Kokkos::atomic_fetch_add(&fill(a), 1)) = 2 * k;
        if (two_sided) {
          const int b = c.second(k);
          ent(off(b) + Kokkos::atomic_fetch_add(&fill(b), 1)) = 2 * k + 1;
        }
      });
  // The fill order above depends on thread timing: sort each particle's few entries by key.
  Kokkos::parallel_for(
      "epac::incidence_sort", Kokkos::RangePolicy<exec>(0, n_particles), KOKKOS_LAMBDA(int i) {
        for (int s = off(i) + 1; s < off(i + 1); ++s) {
          const int e = ent(s);
          const std::uint64_t key = keys(e / 2);
          int t = s - 1;
          while (t >= off(i) && keys(ent(t) / 2) > key) {
            ent(t + 1) = ent(t);
            --t;
          }
          ent(t + 1) = e;
        }
      });
  return inc;
}

// Adds the buffered contact forces and torques to p.force / p.torque, each particle summing its
// contacts in key order.
template <class T, class Device>
void reduce_contact_forces(const Particles<T, Device>& p, const ContactForceBuffer<T, Device>& buf,
                           const ContactIncidence<Device>& inc) {
  using exec = typename Device::execution_space;
  if (inc.entries.extent(0) == 0) return;
  Kokkos::parallel_for(
      "epac::reduce_contact_forces", Kokkos::RangePolicy<exec>(0, p.n), KOKKOS_LAMBDA(int i) {
        Vec3<T> f = load3(p.force, i), t = load3(p.torque, i);
        for (int s = inc.offsets(i); s < inc.offsets(i + 1); ++s) {
          const int k = inc.entries(s) / 2;
          if (inc.entries(s) % 2 == 0) {
            f += load3(buf.force, k);
            t += load3(buf.torque_i, k);
          } else {
            f -= load3(buf.force, k);
            t += load3(buf.torque_j, k);
          }
        }
        store3(p.force, i, f);
        store3(p.torque, i, t);
      });
}

}  // namespace epac
