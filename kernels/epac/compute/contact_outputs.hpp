#pragma once
// What a force pass writes besides the particle sums: optional per-contact outputs, and the
// deterministic mode's per-contact buffer (compute/contact_forces.hpp, compute/pair_lanes.hpp).
#include <Kokkos_Core.hpp>

namespace epac {

// Optional per-contact outputs; leave a view empty to skip it.
template <class T, class Device>
struct ContactOutputs {
  Kokkos::View<T*, Device> normal_force;  // total normal force on i along n (law + damping)
  Kokkos::View<T*, Device> overlap;       // delta
};

// Deterministic mode (docs/design.md section 6): when `force` is allocated, the kernel stores each
// contact's force on its listed first particle (c.first(k)) and the torques on first and second
// here instead of adding them to the sums; compute/deterministic_reduce.hpp then sums them per
// particle in a fixed order. The pair kernel then evaluates every pair in the orientation of the
// smaller global id, so the stored values are the same bits for (i, j) and (j, i).
template <class T, class Device>
struct ContactForceBuffer {
  using vec_view = Kokkos::View<T* [3], Kokkos::LayoutLeft, Device>;
  vec_view force, torque_i, torque_j;
  ContactForceBuffer() = default;
  explicit ContactForceBuffer(int contacts)
      : force("buffer.force", contacts), torque_i("buffer.torque_i", contacts), torque_j("buffer.torque_j", contacts) {}
  KOKKOS_INLINE_FUNCTION bool enabled() const { return force.extent(0) > 0; }
};

}  // namespace epac
