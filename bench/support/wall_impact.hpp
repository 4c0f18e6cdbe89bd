#pragma once
// One sphere hitting a rigid wall head-on, integrated with velocity Verlet through the contact
// kernel (compute_wall_forces). Used by the accuracy-versus-cost report: it measures what a law
// predicts (rebound speed, peak force) at a given time step and precision.
#include <epac/compute/contact_forces.hpp>

#include <cmath>

namespace epac {
namespace bench {

struct ImpactResult {
  double restitution = 0;  // rebound speed / impact speed; 0 if the sphere stuck
  double peak_force = 0;   // largest compressive wall force [N]
  long steps = 0;
  bool finite = true;  // no NaN or Inf seen
};

// `model` has materials {particle = 0, wall = 1}. Starts with a gap of 1e-3 R. The wall sits at
// z = offset (positions are absolute, as in a simulation box of that size); positions and the
// wall point are double for any T (mixed precision), as a particle that far out has them.
template <class Model>
ImpactResult wall_impact(const Model& model, double R, double m, double v0, double dt, double t_max,
                         double offset = 0.0) {
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;
  Particles<T, D> p(1, "impact");
  Walls<T, D> w(1, "wall");
  ContactList<D> c(1, "wall_contact");
  ContactHistory<T, D> h(1, Model::history_size);
  auto x = Kokkos::create_mirror_view(p.x);
  auto v = Kokkos::create_mirror_view(p.v);
  auto f = Kokkos::create_mirror_view(p.force);
  Kokkos::deep_copy(x, 0.0);
  Kokkos::deep_copy(v, T(0));
  Kokkos::deep_copy(p.mass, T(m));
  Kokkos::deep_copy(p.radius, T(R));
  Kokkos::deep_copy(p.radius0, T(R));
  Kokkos::deep_copy(p.inertia, T(0.4 * m * R * R));
  Kokkos::deep_copy(p.material, 0);
  Kokkos::deep_copy(p.gid, 0);
  {
    auto wn = Kokkos::create_mirror_view(w.normal);
    Kokkos::deep_copy(wn, T(0));
    wn(0, 2) = T(1);
    Kokkos::deep_copy(w.normal, wn);
    auto wp = Kokkos::create_mirror_view(w.point);
    Kokkos::deep_copy(wp, 0.0);
    wp(0, 2) = offset;
    Kokkos::deep_copy(w.point, wp);
    Kokkos::deep_copy(w.material, 1);
    Kokkos::deep_copy(c.first, 0);
    Kokkos::deep_copy(c.second, 0);
  }
  // The absolute position is integrated in double, as a simulation far out does: its rounding at
  // the offset is what the offset scan measures.
  double z = offset + R * (1 + 1e-3), vz = -v0;
  ImpactResult r;
  bool touched = false;
  auto force = [&]() {
    x(0, 2) = z;
    v(0, 2) = T(vz);
    Kokkos::deep_copy(p.x, x);
    Kokkos::deep_copy(p.v, v);
    zero_forces(p);
    compute_wall_forces(model, p, w, c, h, T(dt));
    Kokkos::deep_copy(f, p.force);
    return double(f(0, 2));
  };
  double fz = force();
  const long n_max = static_cast<long>(t_max / dt);
  for (long s = 0; s < n_max; ++s) {
    vz += 0.5 * dt * fz / m;
    z += dt * vz;
    fz = force();
    vz += 0.5 * dt * fz / m;
    r.steps = s + 1;
    if (!std::isfinite(fz) || !std::isfinite(vz)) {
      r.finite = false;
      return r;
    }
    if (fz != 0) touched = true;
    r.peak_force = std::max(r.peak_force, fz);
    if (touched && fz == 0 && vz > 0 && z - offset > R) {
      r.restitution = vz / v0;
      return r;
    }
  }
  return r;  // stuck within t_max
}

// Hertz contact duration of a sphere on a rigid wall (Johnson): 2.87 (m^2/(R E*^2 v))^(1/5).
inline double hertz_contact_time(double m, double R, double E_star, double v) {
  return 2.87 * std::pow(m * m / (R * E_star * E_star * v), 0.2);
}

}  // namespace bench
}  // namespace epac
