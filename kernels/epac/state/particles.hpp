#pragma once
// Particle state, structure of arrays (docs/design.md section 3). Each vector quantity is an
// (n x 3) LayoutLeft view, so each component is contiguous.
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

  int n = 0;
  vec_view x, v, omega, force, torque;
  scalar_view mass, inertia;  // inertia: moment of inertia of a solid sphere, (2/5) m R0^2
  scalar_view radius0;        // initial radius R0
  scalar_view radius;         // current (apparent) radius R; equals R0 unless MDR grows it
  Kokkos::View<int*, Device> material;
  Kokkos::View<std::int64_t*, Device> gid;  // global id: history keys and MDR side order
  PeriodicBox<T> box;                       // periodic axes of the contact geometry (default: none)

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

  // Bytes held per particle (reported by the driver).
  static constexpr std::size_t bytes_per_particle() {
    return 15 * sizeof(T) + 4 * sizeof(T) + sizeof(int) + sizeof(std::int64_t);
  }
};

// Zeroes force and torque before a force pass.
template <class T, class Device>
void zero_forces(const Particles<T, Device>& p) {
  Kokkos::deep_copy(p.force, T(0));
  Kokkos::deep_copy(p.torque, T(0));
}

}  // namespace epac
