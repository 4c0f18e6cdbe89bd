#pragma once
// Analytic plane walls (docs/design.md section 3): a point on the plane, a unit normal pointing into
// the domain (towards the particles it touches), a velocity and a material id. The point is
// double whatever T, like Particles::x (mixed precision: the distance to the plane is taken in
// double); normal and velocity are T.
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

  Walls() = default;
  explicit Walls(int count, const std::string& label = "walls")  // host
      : n(count),
        point(label + ".point", count),
        normal(label + ".normal", count),
        velocity(label + ".velocity", count),
        material(label + ".material", count) {}
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
