#pragma once
// The pair-kernel test scene shared by tests/foundation/test_pair_lanes.cpp and
// test_pair_apart.cpp: the dense packing (face neighbours overlap) plus its xy-diagonal
// neighbours (apart), global ids shuffled, materials mixed, one pair of coincident centres, a list
// length that is no multiple of 8; and five passes of a kernel form over it.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/contact_forces.hpp>
#include <support/dense_packing.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

namespace epac {
namespace test {

template <class T, class D>
struct PairScene {
  Particles<T, D> p;
  ContactList<D> c;
};

// The dense packing (face neighbours overlap) plus its xy-diagonal neighbours (apart: 2.69 R
// against 2 R), global ids shuffled, materials mixed, one pair of coincident centres.
// periodic: the packing fills a box periodic on all three axes (one spacing per sphere), and the
// faces' spheres are also listed with the opposite faces' (they touch only through the minimum
// image, with separations of either sign on each axis).
// gid_ordered: each pair listed with its smaller global id first, and the list says so
// (ContactList::gid_ordered, the driver's lists).
template <class T, class D>
PairScene<T, D> pair_scene(double speed, int nmat = 1, bool periodic = false, bool gid_ordered = false) {
  const int n_side = 9;
  auto pk = bench::make_dense_packing<T, D>(n_side);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto gid = Kokkos::create_mirror_view(pk.particles.gid);
  auto mat = Kokkos::create_mirror_view(pk.particles.material);
  auto v = Kokkos::create_mirror_view(pk.particles.v);
  auto x = Kokkos::create_mirror_view(pk.particles.x);
  Kokkos::deep_copy(v, pk.particles.v);
  Kokkos::deep_copy(x, pk.particles.x);
  const int n = pk.particles.n;
  std::vector<std::int64_t> ids(n);
  std::iota(ids.begin(), ids.end(), 0);
  std::shuffle(ids.begin(), ids.end(), rng);
  for (int i = 0; i < n; ++i) {
    gid(i) = ids[i];
    mat(i) = static_cast<int>(rng() % static_cast<unsigned>(nmat));
    for (int d = 0; d < 3; ++d) v(i, d) = T(v(i, d) * speed * std::pow(10.0, 2.0 * u(rng)));
  }
  for (int d = 0; d < 3; ++d) x(1, d) = x(0, d);  // coincident centres: pair (0, 1) is listed
  Kokkos::deep_copy(pk.particles.gid, gid);
  Kokkos::deep_copy(pk.particles.material, mat);
  Kokkos::deep_copy(pk.particles.v, v);
  Kokkos::deep_copy(pk.particles.x, x);
  auto f0 = test::to_host(pk.contacts.first);
  auto s0 = test::to_host(pk.contacts.second);
  std::vector<int> fi, fj;
  for (int k = 0; k < pk.contacts.count; ++k) {
    fi.push_back(f0(k));
    fj.push_back(s0(k));
  }
  auto idx = [n_side](int a, int b, int c) { return (a * n_side + b) * n_side + c; };
  for (int a = 0; a + 1 < n_side; ++a)
    for (int b = 0; b + 1 < n_side; ++b)
      for (int c = 0; c < n_side; c += 2) {
        fi.push_back(idx(a, b, c));
        fj.push_back(idx(a + 1, b + 1, c));
      }
  if (periodic) {
    // the lattice spacing along each axis from the packing's extent; the box: one spacing per sphere
    for (int d = 0; d < 3; ++d) {
      double lo = x(0, d), hi = x(0, d);
      for (int i = 2; i < n; ++i) {  // 1 sits on 0 (the coincident pair)
        lo = std::min(lo, double(x(i, d)));
        hi = std::max(hi, double(x(i, d)));
      }
      const double spacing = (hi - lo) / (n_side - 1);
      pk.particles.box.lo[d] = lo - 0.5 * spacing;
      pk.particles.box.length[d] = n_side * spacing;
    }
    for (int b = 0; b < n_side; b += 2)
      for (int c = 2; c < n_side; c += 3) {  // c = 2: not the coincident sphere 1 = idx(0, 0, 1)
        fi.push_back(idx(0, b, c));          // across the faces of each index, in both list orders
        fj.push_back(idx(n_side - 1, b, c));
        fi.push_back(idx(b, n_side - 1, c));
        fj.push_back(idx(b, 0, c));
        fi.push_back(idx(c, b, 0));
        fj.push_back(idx(c, b, n_side - 1));
      }
  }
  // one more: no multiple of 8, and touching (the face neighbours 5 and 6 listed a second time,
  // the other way round), so that the last block's last lane has a force and a history to store
  fi.push_back(idx(0, 0, 6));
  fj.push_back(idx(0, 0, 5));
  if (gid_ordered)
    for (std::size_t k = 0; k < fi.size(); ++k)
      if (gid(fj[k]) < gid(fi[k])) std::swap(fi[k], fj[k]);
  PairScene<T, D> s{pk.particles, ContactList<D>(static_cast<int>(fi.size()))};
  s.c.gid_ordered = gid_ordered;
  auto hf = Kokkos::create_mirror_view(s.c.first);
  auto hs = Kokkos::create_mirror_view(s.c.second);
  for (std::size_t k = 0; k < fi.size(); ++k) {
    hf(k) = fi[k];
    hs(k) = fj[k];
  }
  Kokkos::deep_copy(s.c.first, hf);
  Kokkos::deep_copy(s.c.second, hs);
  return s;
}

template <class T>
std::vector<Material> pair_materials(double mu, int nmat = 1) {
  Material a;
  a.name = "glass";
  a.youngs_modulus = 70e9;
  a.poisson_ratio = 0.25;
  a.density = 2500;
  a.restitution = 0.5;
  a.friction = mu;
  Material b = a;
  b.name = "steel";
  b.youngs_modulus = 200e9;
  b.poisson_ratio = 0.3;
  b.restitution = 0.7;
  b.friction = mu > 0 ? 0.3 : 0.0;
  if (nmat == 1) return {a};
  return {a, b};
}

// Forces, torques, history and per-contact outputs after 5 passes of one kernel form.
struct PassResult {
  std::vector<double> force, torque, history, normal_force, overlap;
};

// history_start: every history field's value before the first pass (0: fresh contacts; another
// value: springs the separated entries must forget).
template <class Model, class T, class D, class Kernel>
PassResult run_passes(const Model& model, double speed, Kernel kernel, double history_start = 0.0,
                      bool periodic = false, bool gid_ordered = false) {
  auto s = pair_scene<T, D>(speed, model.nmat, periodic, gid_ordered);
  ContactHistory<T, D> h(s.c.count, Model::history_size);
  if (history_start != 0.0 && h.data.span() > 0) Kokkos::deep_copy(h.data, T(history_start));
  ContactOutputs<T, D> out{Kokkos::View<T*, D>("fn", s.c.count), Kokkos::View<T*, D>("delta", s.c.count)};
  const ForceSums<T, D, AtomicSums> sums(s.p);
  for (int pass = 0; pass < 5; ++pass) {
    zero_forces(s.p);
    kernel(model, s.p, s.c, h, T(2e-7), sums, out);
  }
  auto flat = [](const auto& view) {
    auto hv = test::to_host(view);
    std::vector<double> r(hv.span());
    for (std::size_t e = 0; e < hv.span(); ++e) r[e] = double(hv.data()[e]);
    return r;
  };
  return {flat(s.p.force), flat(s.p.torque), h.data.span() ? flat(h.data) : std::vector<double>{},
          flat(out.normal_force), flat(out.overlap)};
}

inline double max_abs(const std::vector<double>& a) {
  double m = 0;
  for (double x : a) m = std::max(m, std::abs(x));
  return m;
}

inline void check_close(const std::vector<double>& a, const std::vector<double>& b, double rel, const char* what) {
  INFO(what);
  REQUIRE(a.size() == b.size());
  const double scale = std::max(max_abs(a), max_abs(b));
  double diff = 0;
  for (std::size_t e = 0; e < a.size(); ++e) diff = std::max(diff, std::abs(a[e] - b[e]));
  CHECK(diff <= rel * scale);
}

}  // namespace test
}  // namespace epac
