#pragma once
// A random dense packing for tests and benchmarks: spheres on a jittered simple-cubic lattice
// with spacing s < 2R, so each sphere overlaps its face neighbours (about 6 contacts per
// particle, fewer at the surface). Contacts are found from the lattice structure (no search).
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace epac {
namespace bench {

template <class T, class Device>
struct DensePacking {
  Particles<T, Device> particles;
  ContactList<Device> contacts;
};

// n_side^3 particles of radius R (+-5%), spacing 1.9 R, jitter 0.02 R, random velocities and
// spins so damping and friction do real work.
template <class T, class Device>
DensePacking<T, Device> make_dense_packing(int n_side, double R = 1e-3, unsigned seed = 7) {
  const int n = n_side * n_side * n_side;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Particles<T, Device> p(n, "packing");
  auto x = Kokkos::create_mirror_view(p.x);
  auto v = Kokkos::create_mirror_view(p.v);
  auto w = Kokkos::create_mirror_view(p.omega);
  auto m = Kokkos::create_mirror_view(p.mass);
  auto I = Kokkos::create_mirror_view(p.inertia);
  auto r0 = Kokkos::create_mirror_view(p.radius0);
  auto r = Kokkos::create_mirror_view(p.radius);
  auto mat = Kokkos::create_mirror_view(p.material);
  auto gid = Kokkos::create_mirror_view(p.gid);
  const double s = 1.9 * R;
  auto idx = [n_side](int a, int b, int c) { return (a * n_side + b) * n_side + c; };
  for (int a = 0; a < n_side; ++a)
    for (int b = 0; b < n_side; ++b)
      for (int c = 0; c < n_side; ++c) {
        const int i = idx(a, b, c);
        const double Ri = R * (1.0 + 0.05 * u(rng));
        x(i, 0) = a * s + 0.02 * R * u(rng);
        x(i, 1) = b * s + 0.02 * R * u(rng);
        x(i, 2) = c * s + 0.02 * R * u(rng);
        for (int d = 0; d < 3; ++d) {
          v(i, d) = T(0.01 * u(rng));
          w(i, d) = T(1.0 * u(rng));
        }
        r0(i) = r(i) = T(Ri);
        m(i) = T(2500.0 * 4.0 / 3.0 * M_PI * Ri * Ri * Ri);
        I(i) = T(0.4 * m(i) * Ri * Ri);
        mat(i) = 0;
        gid(i) = i;
      }
  std::vector<int> fi, fj;  // host
  for (int a = 0; a < n_side; ++a)
    for (int b = 0; b < n_side; ++b)
      for (int c = 0; c < n_side; ++c) {
        if (a + 1 < n_side) {
          fi.push_back(idx(a, b, c));
          fj.push_back(idx(a + 1, b, c));
        }
        if (b + 1 < n_side) {
          fi.push_back(idx(a, b, c));
          fj.push_back(idx(a, b + 1, c));
        }
        if (c + 1 < n_side) {
          fi.push_back(idx(a, b, c));
          fj.push_back(idx(a, b, c + 1));
        }
      }
  // Shuffle the list so memory access is not artificially regular.
  std::vector<int> order(fi.size());  // host
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::shuffle(order.begin(), order.end(), rng);
  ContactList<Device> cl(static_cast<int>(fi.size()), "packing.contacts");
  auto hf = Kokkos::create_mirror_view(cl.first);
  auto hs = Kokkos::create_mirror_view(cl.second);
  for (std::size_t k = 0; k < order.size(); ++k) {
    hf(k) = fi[order[k]];
    hs(k) = fj[order[k]];
  }
  Kokkos::deep_copy(cl.first, hf);
  Kokkos::deep_copy(cl.second, hs);
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.omega, w);
  Kokkos::deep_copy(p.mass, m);
  Kokkos::deep_copy(p.inertia, I);
  Kokkos::deep_copy(p.radius0, r0);
  Kokkos::deep_copy(p.radius, r);
  Kokkos::deep_copy(p.material, mat);
  Kokkos::deep_copy(p.gid, gid);
  return {p, cl};
}

}  // namespace bench
}  // namespace epac
