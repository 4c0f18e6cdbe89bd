#pragma once
// Analytic plane walls (docs/design.md section 3): a point on the plane, a unit normal pointing into
// the domain (towards the particles it touches), a velocity, a material id and the surface's
// radius of curvature there. The point is double whatever T, like Particles::x (mixed precision:
// the distance to the plane is taken in double); normal, velocity and curvature are T.
// curvature: LAMMPS's region contact radius (Region::contact[].radius): 0 for a flat surface (the
// constructor's value), > 0 convex (a sphere's outside: its radius), < 0 concave (a cylinder's
// inside: -2 R_cyl, a sphere's inside: -R_sph). It only sets the contact's R* (R_eff of
// ContactGeometry: R_i R_w / (R_i + R_w), LAMMPS's Reff; compute/contact_forces.hpp); the contact
// itself is still the particle against the tangent plane at `point`. Concave radii need
// -R_w >= 2 R_i (R* <= 2 R_i; validate(particles, walls, model)).
#include <epac/core/kokkos_compat.hpp>

#include <string>

namespace epac {

template <class T, class Device = DefaultDevice>
struct Walls {
  using vec_view = Kokkos::View<T* [3], Kokkos::LayoutLeft, Device>;
  using position_type = double;
  using position_view = Kokkos::View<position_type* [3], Kokkos::LayoutLeft, Device>;
  int n = 0;
  position_view point;
  vec_view normal, velocity;
  Kokkos::View<int*, Device> material;
  Kokkos::View<T*, Device> curvature;  // zero (flat) unless the host sets it

  Walls() = default;
  explicit Walls(int count, const std::string& label = "walls")  // host
      : n(count),
        point(label + ".point", count),
        normal(label + ".normal", count),
        velocity(label + ".velocity", count),
        material(label + ".material", count),
        curvature(label + ".curvature", count) {}
};

// Moves every wall by its velocity over dt (prescribed-displacement driving), in double.
template <class T, class Device>
void advance_walls(const Walls<T, Device>& w, T dt) {
  using P = typename Walls<T, Device>::position_type;
  using exec = typename Device::execution_space;
  auto p = w.point;
  auto v = w.velocity;
  Kokkos::parallel_for(
      "epac::advance_walls", Kokkos::RangePolicy<exec>(0, w.n), KOKKOS_LAMBDA(int k) {
        for (int d = 0; d < 3; ++d) p(k, d) += P(dt) * P(v(k, d));
      });
}

}  // namespace epac
