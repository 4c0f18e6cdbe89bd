#pragma once
// Device reductions behind one timeseries sample: energies, active contact counts, the largest
// relative overlap, per-wall normal force, and the contact force on driven particles.
// Sums go through ordered_sum (fixed order: the same bits on any thread count, so a run in the
// deterministic mode writes the same timeseries.csv on 1 or 2 threads); counts and maxima are exact.
#include "driver/sample.hpp"

#include <epac/compute/contact_forces.hpp>
#include <epac/compute/ordered_sum.hpp>
#include <epac/core/vec3.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>

namespace epac {
namespace driver {

// Fills the particle and contact parts of s. pair_out / wall_out are the per-contact outputs of
// the force pass that produced the current forces (their length is the list's count).
template <class T, class Device>
void sample_state(const Particles<T, Device>& p, const Kokkos::View<unsigned char*, Device>& driven, bool any_driven,
                  const Vec3<T>& gravity, const ContactList<Device>& pairs, const ContactList<Device>& walls,
                  const ContactOutputs<T, Device>& pair_out, const ContactOutputs<T, Device>& wall_out, int nwalls,
                  Sample& s) {
  using exec = typename Device::execution_space;
  const int n = p.n;
  auto x = p.x;
  auto v = p.v;
  auto w = p.omega;
  auto m = p.mass;
  auto I = p.inertia;
  auto R = p.radius;
  const double ke = ordered_sum<exec>("epac::driver::ke_trans", n,
      KOKKOS_LAMBDA(int i) { return 0.5 * double(m(i)) * double(dot(load3(v, i), load3(v, i))); });
  const double kr = ordered_sum<exec>("epac::driver::ke_rot", n,
      KOKKOS_LAMBDA(int i) { return 0.5 * double(I(i)) * double(dot(load3(w, i), load3(w, i))); });
  const double pe = ordered_sum<exec>("epac::driver::pe_gravity", n,
      KOKKOS_LAMBDA(int i) { return -double(m(i)) * double(dot(gravity, load3(x, i))); });
  s.ke_translational = ke;
  s.ke_rotational = kr;
  s.pe_gravity = pe;

  s.pair_list = pairs.count;
  s.wall_list = walls.count;
  int np = 0, nw = 0;
  T ratio_p = T(0), ratio_w = T(0);
  if (pairs.count > 0) {
    auto ov = pair_out.overlap;
    auto a = pairs.first;
    auto b = pairs.second;
    Kokkos::parallel_reduce("epac::driver::pair_active", Kokkos::RangePolicy<exec>(0, pairs.count),
        KOKKOS_LAMBDA(int k, int& c) { if (ov(k) > T(0)) ++c; }, np);
    Kokkos::parallel_reduce("epac::driver::pair_max_overlap", Kokkos::RangePolicy<exec>(0, pairs.count),
        KOKKOS_LAMBDA(int k, T& r) {
          const T q = ov(k) / math::min(R(a(k)), R(b(k)));  // radii > 0
          if (q > r) r = q;
        },
        Kokkos::Max<T>(ratio_p));
  }
  if (walls.count > 0) {
    auto ov = wall_out.overlap;
    auto a = walls.first;
    Kokkos::parallel_reduce("epac::driver::wall_active", Kokkos::RangePolicy<exec>(0, walls.count),
        KOKKOS_LAMBDA(int k, int& c) { if (ov(k) > T(0)) ++c; }, nw);
    Kokkos::parallel_reduce("epac::driver::wall_max_overlap", Kokkos::RangePolicy<exec>(0, walls.count),
        KOKKOS_LAMBDA(int k, T& r) {
          const T q = ov(k) / R(a(k));
          if (q > r) r = q;
        },
        Kokkos::Max<T>(ratio_w));
  }
  s.pair_contacts = np;
  s.wall_contacts = nw;
  s.max_overlap_ratio = static_cast<double>(math::max(math::max(ratio_p, ratio_w), T(0)));

  s.wall_force.assign(nwalls, 0.0);
  if (nwalls > 0 && walls.count > 0) {
    auto fn = wall_out.normal_force;
    auto wl = walls.second;
    for (int wall = 0; wall < nwalls; ++wall)
      s.wall_force[wall] = ordered_sum<exec>("epac::driver::wall_force", walls.count,
          KOKKOS_LAMBDA(int k) { return wl(k) == wall ? double(fn(k)) : 0.0; });
  }

  s.driven_force = {0, 0, 0};
  if (any_driven) {
    auto f = p.force;
    for (int d = 0; d < 3; ++d)
      s.driven_force[d] = ordered_sum<exec>("epac::driver::driven_force", n,
          KOKKOS_LAMBDA(int i) { return driven(i) ? double(f(i, d)) : 0.0; });
  }
}

}  // namespace driver
}  // namespace epac
