#pragma once
// Minimal velocity-Verlet stepper for kernel tests (the driver has the full one): pair and wall
// contacts from fixed lists, translation and rotation, on the device.
#include <epac/compute/contact_forces.hpp>

namespace epac {
namespace test {

template <class Model, class T, class D>
struct VerletStepper {
  Model model;
  Particles<T, D> p;
  ContactList<D> pairs;
  ContactHistory<T, D> pair_hist;
  Walls<T, D> walls;
  ContactList<D> wall_contacts;
  ContactHistory<T, D> wall_hist;
  T dt;
  ContactOutputs<T, D> pair_out, wall_out;

  void forces() {
    zero_forces(p);
    if (pairs.count > 0) compute_pair_forces(model, p, pairs, pair_hist, dt, pair_out);
    if (wall_contacts.count > 0) compute_wall_forces(model, p, walls, wall_contacts, wall_hist, dt, wall_out);
  }
  void half_kick() {
    auto pp = p;
    const T h = T(0.5) * dt;
    Kokkos::parallel_for(
        Kokkos::RangePolicy<typename D::execution_space>(0, p.n), KOKKOS_LAMBDA(int i) {
          for (int d = 0; d < 3; ++d) {
            pp.v(i, d) += h * pp.force(i, d) / pp.mass(i);
            pp.omega(i, d) += h * pp.torque(i, d) / pp.inertia(i);
          }
        });
  }
  void drift() {
    auto pp = p;
    const T h = dt;
    Kokkos::parallel_for(
        Kokkos::RangePolicy<typename D::execution_space>(0, p.n), KOKKOS_LAMBDA(int i) {
          for (int d = 0; d < 3; ++d) pp.x(i, d) += h * pp.v(i, d);
        });
    if (walls.n > 0) advance_walls(walls, dt);
  }
  void start() { forces(); }
  void step() {
    half_kick();
    drift();
    forces();
    half_kick();
  }
};

// Two spheres (gid 0 and 1) of radius R and mass m approaching head-on along x, at relative
// speed v0, initially `gap` apart (surface to surface).
template <class T, class D>
Particles<T, D> two_spheres(double R, double m, double v0, double gap, double offset_y = 0.0) {
  Particles<T, D> p(2, "two");
  auto x = Kokkos::create_mirror_view(p.x);
  auto v = Kokkos::create_mirror_view(p.v);
  auto ms = Kokkos::create_mirror_view(p.mass);
  auto I = Kokkos::create_mirror_view(p.inertia);
  auto r = Kokkos::create_mirror_view(p.radius);
  auto gid = Kokkos::create_mirror_view(p.gid);
  Kokkos::deep_copy(x, T(0));
  Kokkos::deep_copy(v, T(0));
  x(0, 0) = T(-(R + 0.5 * gap));
  x(1, 0) = T(R + 0.5 * gap);
  x(0, 1) = T(-0.5 * offset_y);
  x(1, 1) = T(0.5 * offset_y);
  v(0, 0) = T(0.5 * v0);
  v(1, 0) = T(-0.5 * v0);
  for (int i = 0; i < 2; ++i) {
    ms(i) = T(m);
    I(i) = T(0.4 * m * R * R);
    r(i) = T(R);
    gid(i) = i;
  }
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.mass, ms);
  Kokkos::deep_copy(p.inertia, I);
  Kokkos::deep_copy(p.radius, r);
  Kokkos::deep_copy(p.radius0, r);
  Kokkos::deep_copy(p.gid, gid);
  Kokkos::deep_copy(p.material, 0);
  return p;
}

template <class D>
ContactList<D> single_pair() {
  ContactList<D> c(1, "pair");
  Kokkos::deep_copy(c.first, 0);
  Kokkos::deep_copy(c.second, 1);
  return c;
}

}  // namespace test
}  // namespace epac
