#pragma once
// The device particle state of a scene: positions, velocities, masses, inertias, radii, materials
// and global ids from the scene's particle specs, and the per-particle driven flags (a driven
// particle keeps its prescribed velocity: the integrator skips it).
#include "driver/scene.hpp"

#include <epac/state/particles.hpp>

namespace epac {
namespace driver {

// Device particle state from the scene's particles.
template <class T, class Device>
Particles<T, Device> make_particles(const Scene& s, Kokkos::View<unsigned char*, Device>& driven) {
  const int n = static_cast<int>(s.particles.size());
  Particles<T, Device> p(n);
  driven = Kokkos::View<unsigned char*, Device>("epac::driver::driven", n);
  auto x = Kokkos::create_mirror_view(p.x);
  auto v = Kokkos::create_mirror_view(p.v);
  auto w = Kokkos::create_mirror_view(p.omega);
  auto m = Kokkos::create_mirror_view(p.mass);
  auto I = Kokkos::create_mirror_view(p.inertia);
  auto r0 = Kokkos::create_mirror_view(p.radius0);
  auto mat = Kokkos::create_mirror_view(p.material);
  auto gid = Kokkos::create_mirror_view(p.gid);
  auto dr = Kokkos::create_mirror_view(driven);
  for (int i = 0; i < n; ++i) {
    const ParticleSpec& q = s.particles[i];
    const double mass = sphere_mass(s.materials[q.material].density, q.radius);
    for (int d = 0; d < 3; ++d) {
      x(i, d) = q.position[d];  // double whatever T (mixed precision)
      v(i, d) = T(q.velocity[d]);
      w(i, d) = T(q.angular_velocity[d]);
    }
    m(i) = T(mass);
    I(i) = T(0.4 * mass * q.radius * q.radius);
    r0(i) = T(q.radius);
    mat(i) = q.material;
    gid(i) = i;
    dr(i) = q.driven ? 1 : 0;
  }
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.omega, w);
  Kokkos::deep_copy(p.mass, m);
  Kokkos::deep_copy(p.inertia, I);
  Kokkos::deep_copy(p.radius0, r0);
  Kokkos::deep_copy(p.radius, r0);
  Kokkos::deep_copy(p.material, mat);
  Kokkos::deep_copy(p.gid, gid);
  Kokkos::deep_copy(driven, dr);
  return p;
}

}  // namespace driver
}  // namespace epac
