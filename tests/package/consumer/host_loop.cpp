// A complete host program: the host owns particles, neighbour search and integration; epac
// computes contact forces. docs/install.md shows this file verbatim (a test compares them) and
// the test install_and_find_package builds and runs it against an installed, moved epac.
#include <epac/compute/contact_forces.hpp>
#include <epac/compute/history_remap.hpp>
#include <epac/core/build_info.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/params/state_validation.hpp>
#include <epac/version.hpp>

#include <cmath>
#include <cstdio>

static_assert(EPAC_VERSION >= EPAC_VERSION_NUMBER(0, 1, 0), "this program needs epac 0.1 or newer");

using Model = epac::HertzMindlin<double, epac::Effects<epac::kFriction | epac::kDamping>>;
using Particles = epac::Particles<double>;
using Walls = epac::Walls<double>;

// The host's neighbour search (all pairs here; a cell list in a real code): pairs closer than
// R_i + R_j + skin, and particle-wall contacts closer than R + skin.
void find_contacts(const Particles& p, const Walls& w, double skin, epac::ContactList<>& pairs,
                   epac::ContactList<>& wall_contacts) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.x);
  auto R = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.radius);
  auto wp = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), w.point);
  auto wn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), w.normal);
  epac::ContactList<Kokkos::HostSpace> hp(p.n * p.n), hw(p.n * w.n);
  int np = 0, nw = 0;
  for (int i = 0; i < p.n; ++i) {
    for (int j = i + 1; j < p.n; ++j) {
      double d2 = 0;
      for (int k = 0; k < 3; ++k) d2 += (x(i, k) - x(j, k)) * (x(i, k) - x(j, k));
      if (std::sqrt(d2) < R(i) + R(j) + skin) {
        hp.first(np) = i;
        hp.second(np) = j;
        ++np;
      }
    }
    for (int k = 0; k < w.n; ++k) {
      double h = 0;  // height above the wall plane
      for (int d = 0; d < 3; ++d) h += (x(i, d) - wp(k, d)) * wn(k, d);
      if (h < R(i) + skin) {
        hw.first(nw) = i;
        hw.second(nw) = k;
        ++nw;
      }
    }
  }
  pairs = epac::ContactList<>(np);
  wall_contacts = epac::ContactList<>(nw);
  Kokkos::deep_copy(pairs.first, Kokkos::subview(hp.first, Kokkos::make_pair(0, np)));
  Kokkos::deep_copy(pairs.second, Kokkos::subview(hp.second, Kokkos::make_pair(0, np)));
  Kokkos::deep_copy(wall_contacts.first, Kokkos::subview(hw.first, Kokkos::make_pair(0, nw)));
  Kokkos::deep_copy(wall_contacts.second, Kokkos::subview(hw.second, Kokkos::make_pair(0, nw)));
}

int main(int argc, char* argv[]) {
  Kokkos::ScopeGuard guard(argc, argv);
  std::printf("%s\n", epac::build_info().c_str());  // epac 0.1.0 (Kokkos 3.4.1: Serial OpenMP)

  // Materials: index 0 for the beads, index 1 for the wall (a wall needs its own entry).
  epac::Material glass{"glass", 70e9, 0.25, 2500, 0.5, 0.3};  // E, nu, density, e0, mu
  epac::Material steel{"steel", 200e9, 0.3, 7800, 0.5, 0.3};
  steel.rigid = true;
  const Model model = Model::create({glass, steel});  // validates on the host, throws ParameterError

  // Three glass beads, R = 1 mm: 0 and 1 approach head-on, 2 hits the floor at a slant.
  const int n = 3;
  const double pi = 3.14159265358979323846, R = 1e-3, mass = 2500 * 4.0 / 3.0 * pi * R * R * R;
  Particles p(n);
  {
    auto x = Kokkos::create_mirror_view(p.x), v = Kokkos::create_mirror_view(p.v);
    auto gid = Kokkos::create_mirror_view(p.gid);
    const double x0[n][3] = {{-1.001e-3, 5e-3, 0}, {1.001e-3, 5e-3, 0}, {0, 1.001e-3, 0}};
    const double v0[n][3] = {{0.1, 0, 0}, {-0.1, 0, 0}, {0.05, -0.1, 0}};
    for (int i = 0; i < n; ++i) {
      for (int d = 0; d < 3; ++d) {
        x(i, d) = x0[i][d];
        v(i, d) = v0[i][d];
      }
      gid(i) = 100 + i;  // global ids: unique and >= 0 (they key the contact history)
    }
    Kokkos::deep_copy(p.x, x);
    Kokkos::deep_copy(p.v, v);
    Kokkos::deep_copy(p.gid, gid);
  }
  // Every field a law reads must be set: radius (current) and radius0 (initial), mass, inertia
  // (solid sphere 2/5 m R^2), material (an index into the list given to create).
  Kokkos::deep_copy(p.radius, R);
  Kokkos::deep_copy(p.radius0, R);
  Kokkos::deep_copy(p.mass, mass);
  Kokkos::deep_copy(p.inertia, 0.4 * mass * R * R);
  Kokkos::deep_copy(p.material, 0);

  Walls walls(1);  // the floor y = 0; the normal is a unit vector pointing to the particles
  {
    auto nrm = Kokkos::create_mirror_view(walls.normal);
    auto mat = Kokkos::create_mirror_view(walls.material);
    nrm(0, 1) = 1.0;
    mat(0) = 1;
    Kokkos::deep_copy(walls.normal, nrm);
    Kokkos::deep_copy(walls.material, mat);
  }
  epac::validate(p, walls, model);  // host: material indices, radii, masses, ids, unit normals

  // Contact lists and their histories, keyed by the contacts' global ids.
  const double skin = 1e-5;
  epac::ContactList<> pairs, wall_contacts;
  find_contacts(p, walls, skin, pairs, wall_contacts);
  epac::ContactHistory<double> pair_history(epac::pair_contact_keys(p, pairs), Model::history_size);
  epac::ContactHistory<double> wall_history(epac::wall_contact_keys(p, wall_contacts), Model::history_size);

  const double dt = 2e-8;
  for (int step = 0; step < 3000; ++step) {
    if (step % 20 == 0) {  // the host's rebuild (skin / displacement criterion in a real code)
      find_contacts(p, walls, skin, pairs, wall_contacts);
      pair_history = epac::remap_history(pair_history, epac::pair_contact_keys(p, pairs), Model::history_size);
      wall_history = epac::remap_history(wall_history, epac::wall_contact_keys(p, wall_contacts), Model::history_size);
    }
    epac::zero_forces(p);
    epac::compute_pair_forces(model, p, pairs, pair_history, dt);  // adds into p.force / p.torque
    epac::compute_wall_forces(model, p, walls, wall_contacts, wall_history, dt);
    Kokkos::parallel_for(
        "integrate", n, KOKKOS_LAMBDA(int i) {  // the host's integrator (semi-implicit Euler)
          for (int d = 0; d < 3; ++d) {
            p.v(i, d) += dt * p.force(i, d) / p.mass(i);
            p.x(i, d) += dt * p.v(i, d);
            p.omega(i, d) += dt * p.torque(i, d) / p.inertia(i);
          }
        });
  }
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.v);
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.omega);
  std::printf("after impact: v0_x = %.4f, v1_x = %.4f, v2_y = %.4f m/s, omega2_z = %.2f rad/s\n", v(0, 0), v(1, 0),
              v(2, 1), w(2, 2));
  const bool bounced = v(0, 0) < 0 && v(1, 0) > 0 && v(2, 1) > 0;
  const bool spun = w(2, 2) < 0;  // friction at the floor rolls bead 2 forward (+x): omega_z < 0
  return bounced && spun ? 0 : 1;
}
