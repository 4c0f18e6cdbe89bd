#pragma once
// Velocity-Verlet integration of translation and rotation (docs/design.md section 4, step 5):
//   v += dt/2 (F/m + g),  omega += dt/2 torque / I     (half kick, from the forces of the last pass)
//   x += dt v                                          (drift; in kick_drift)
//   ... contact detection, forces ...
//   v += dt/2 (F/m + g),  omega += dt/2 torque / I     (half kick, from the new forces)
// Positions are double whatever T (mixed precision, state/particles.hpp): the drift adds the
// T velocity times the double dt in double, so a step smaller than a float coordinate's spacing
// still moves the particle.
// Spheres: I = (2/5) m R0^2 (Particles::inertia). Driven particles keep their prescribed
// velocity and angular velocity: they drift but are never kicked.
// kick_drift fuses the closing half kick of one step with the opening half kick and drift of the
// next (kick_dt = dt), the box deformation's remap of the positions, zeroes the consumed forces
// (where the force pass does not overwrite them) and measures the displacement for the rebuild
// rule, all in one pass: 1 parallel region instead of 6, which matters most on busy cores.
#include "driver/box_motion.hpp"

#include <epac/core/vec3.hpp>
#include <epac/state/particles.hpp>

namespace epac {
namespace driver {

// mass and inertia are > 0 (the host refuses particle materials without a positive density).
template <class T, class Device>
void half_kick(const Particles<T, Device>& p, const Kokkos::View<unsigned char*, Device>& driven,
               const Vec3<T>& gravity, T half_dt) {
  using exec = typename Device::execution_space;
  auto v = p.v;
  auto w = p.omega;
  auto f = p.force;
  auto tq = p.torque;
  auto m = p.mass;
  auto I = p.inertia;
  Kokkos::parallel_for(
      "epac::driver::half_kick", Kokkos::RangePolicy<exec>(0, p.n), KOKKOS_LAMBDA(int i) {
        if (driven(i)) return;
        const T inv_m = T(1) / m(i);
        const T inv_I = T(1) / I(i);
        v(i, 0) += half_dt * (f(i, 0) * inv_m + gravity.x);
        v(i, 1) += half_dt * (f(i, 1) * inv_m + gravity.y);
        v(i, 2) += half_dt * (f(i, 2) * inv_m + gravity.z);
        for (int d = 0; d < 3; ++d) w(i, d) += half_dt * tq(i, d) * inv_I;
      });
}

// v += kick_dt (F/m + g), omega += kick_dt torque/I (not for driven particles); force = torque
// = 0 (unless !zero_forces: the next pass overwrites them, ForceSums::end(true));
// x = remap(x) + dt v in double (remap: a box deformation's affine map, when active).
// Returns max_i (|x_i - x_ref_i| + max(0, R_i - R_ref_i)), the rebuild measure of
// ContactDetector (a non-finite position returns 1e30 so that the rebuild reports it).
template <class T, class Device>
T kick_drift(const Particles<T, Device>& p, const Kokkos::View<unsigned char*, Device>& driven, const Vec3<T>& gravity,
             T kick_dt, typename Particles<T, Device>::position_type dt,
             const typename Particles<T, Device>::position_view& x_ref, const Kokkos::View<T*, Device>& r_ref,
             const AffineRemap<typename Particles<T, Device>::position_type>& remap = {}, bool zero_forces = true) {
  using exec = typename Device::execution_space;
  using P = typename Particles<T, Device>::position_type;
  auto x = p.x;
  auto v = p.v;
  auto w = p.omega;
  auto f = p.force;
  auto tq = p.torque;
  auto m = p.mass;
  auto I = p.inertia;
  auto R = p.radius;
  T shift = T(0);
  Kokkos::parallel_reduce(
      "epac::driver::kick_drift", Kokkos::RangePolicy<exec>(0, p.n),
      KOKKOS_LAMBDA(int i, T& s) {
        if (!driven(i)) {
          const T inv_m = T(1) / m(i);
          const T inv_I = T(1) / I(i);
          v(i, 0) += kick_dt * (f(i, 0) * inv_m + gravity.x);
          v(i, 1) += kick_dt * (f(i, 1) * inv_m + gravity.y);
          v(i, 2) += kick_dt * (f(i, 2) * inv_m + gravity.z);
          for (int d = 0; d < 3; ++d) w(i, d) += kick_dt * tq(i, d) * inv_I;
        }
        for (int d = 0; d < 3; ++d) {
          if (zero_forces) {
            f(i, d) = T(0);
            tq(i, d) = T(0);
          }
          const P xd = remap.active ? remap(x(i, d), d) : x(i, d);
          x(i, d) = xd + dt * P(v(i, d));
        }
        const T grow = R(i) - r_ref(i);
        const T si = T(norm(load3(x, i) - load3(x_ref, i))) + (grow > T(0) ? grow : T(0));
        if (!(si == si))
          s = T(1e30);
        else if (si > s)
          s = si;
      },
      Kokkos::Max<T>(shift));
  return shift;
}

}  // namespace driver
}  // namespace epac
