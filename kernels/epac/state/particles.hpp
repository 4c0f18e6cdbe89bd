#pragma once
// Particle state, structure of arrays (docs/design.md section 3). Each vector quantity is an
// (n x 3) LayoutLeft view, so each component is contiguous.
// Mixed precision: positions are always double (position_type), whatever T. A float coordinate
// 10 m from the origin has a spacing of 1 um, coarser than a typical step's displacement, so a
// particle away from the origin would stop moving; the contact geometry is therefore computed
// from double positions too and only its small results (overlap, normal, arms) reach the law in
// T. Velocities, forces, torques, radii and masses are T.
#include <epac/core/kokkos_compat.hpp>
#include <epac/state/periodic_box.hpp>

#include <cstdint>
#include <string>

namespace epac {

template <class T, class Device = DefaultDevice>
struct Particles {
  using scalar_type = T;
  using device_type = Device;
  using vec_view = Kokkos::View<T* [3], Kokkos::LayoutLeft, Device>;
  using scalar_view = Kokkos::View<T*, Device>;
  using position_type = double;
  using position_view = Kokkos::View<position_type* [3], Kokkos::LayoutLeft, Device>;

  int n = 0;
  position_view x;
  vec_view v, omega, force, torque;
  scalar_view mass, inertia;  // inertia: moment of inertia of a solid sphere, (2/5) m R0^2
  scalar_view radius0;        // initial radius R0
  scalar_view radius;         // current (apparent) radius R; equals R0 unless MDR grows it
  Kokkos::View<int*, Device> material;
  Kokkos::View<std::int64_t*, Device> gid;  // global id: history keys and MDR side order
  PeriodicBox<position_type> box;           // periodic axes of the contact geometry (default: none)

  Particles() = default;
  explicit Particles(int count, const std::string& label = "particles")  // host
      : n(count),
        x(label + ".x", count),
        v(label + ".v", count),
        omega(label + ".omega", count),
        force(label + ".force", count),
        torque(label + ".torque", count),
        mass(label + ".mass", count),
        inertia(label + ".inertia", count),
        radius0(label + ".radius0", count),
        radius(label + ".radius", count),
        material(label + ".material", count),
        gid(label + ".gid", count) {}

  // Bytes held per particle: x in double, v, omega, force, torque (12) and mass, inertia,
  // radius0, radius (4) in T, material, gid: 164 in double, 100 in float (88 before positions
  // were double).
  static constexpr std::size_t bytes_per_particle() {
    return 3 * sizeof(position_type) + 12 * sizeof(T) + 4 * sizeof(T) + sizeof(int) + sizeof(std::int64_t);
  }
};

// Zeroes force and torque before a force pass.
template <class T, class Device>
void zero_forces(const Particles<T, Device>& p) {
  Kokkos::deep_copy(p.force, T(0));
  Kokkos::deep_copy(p.torque, T(0));
}

}  // namespace epac
