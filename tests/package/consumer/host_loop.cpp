// The README's host loop: a host owns particles, contacts and integration; epac computes forces.
#include <epac/compute/contact_forces.hpp>
#include <epac/models/hertz_mindlin.hpp>

#include <cstdio>

void instantiate_all_models();  // all_models.cpp

int main(int argc, char* argv[]) {
  Kokkos::ScopeGuard guard(argc, argv);
  using Model = epac::HertzMindlin<double, epac::Effects<epac::kFriction | epac::kDamping>>;
  epac::Material glass{"glass", 70e9, 0.25, 2500, 0.5, 0.3};  // E, nu, density, e0, mu
  const Model model = Model::create({glass});

  epac::Particles<double> p(2);  // two spheres, 1 mm, approaching head-on
  auto x = Kokkos::create_mirror_view(p.x), v = Kokkos::create_mirror_view(p.v);
  x(0, 0) = -1.0e-3; x(1, 0) = 1.0e-3; v(0, 0) = 0.1; v(1, 0) = -0.1;
  Kokkos::deep_copy(p.x, x); Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.radius, 1e-3); Kokkos::deep_copy(p.mass, 1.05e-5);
  Kokkos::deep_copy(p.inertia, 4.2e-12); Kokkos::deep_copy(p.material, 0);
  Kokkos::parallel_for(2, KOKKOS_LAMBDA(int i) { p.gid(i) = i; });

  epac::ContactList<> pairs(1);  // from the host's neighbour search
  Kokkos::deep_copy(pairs.first, 0); Kokkos::deep_copy(pairs.second, 1);
  epac::ContactHistory<double> history(pairs.count, Model::history_size);

  const double dt = 1e-8;
  for (int step = 0; step < 2000; ++step) {  // the host's integrator (explicit Euler here)
    epac::zero_forces(p);
    epac::compute_pair_forces(model, p, pairs, history, dt);
    Kokkos::parallel_for(2, KOKKOS_LAMBDA(int i) {
      for (int d = 0; d < 3; ++d) { p.v(i, d) += dt * p.force(i, d) / p.mass(i); p.x(i, d) += dt * p.v(i, d); }
    });
  }
  instantiate_all_models();
  Kokkos::deep_copy(v, p.v);
  std::printf("velocity after impact: %.4f %.4f m/s\n", v(0, 0), v(1, 0));
  return (v(0, 0) < 0 && v(1, 0) > 0) ? 0 : 1;  // they bounced
}
