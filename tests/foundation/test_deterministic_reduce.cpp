// Deterministic mode gives the same bits for any thread count and any contact-list order, and
// agrees with the atomic path to round-off.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/deterministic_reduce.hpp>
#include <epac/compute/history_remap.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <support/dense_packing.hpp>

#include <algorithm>
#include <random>

using namespace epac;

namespace {
Material glass() {
  Material m;
  m.name = "glass";
  m.youngs_modulus = 70e9;
  m.poisson_ratio = 0.25;
  m.density = 2500;
  m.restitution = 0.5;
  m.friction = 0.5;
  return m;
}
template <class T, class D>
auto forces(bool deterministic, bool reverse_list) {
  using Model = HertzMindlin<T, Effects<kFriction | kDamping>, D>;
  auto pk = bench::make_dense_packing<T, D>(12);
  if (reverse_list) {  // same contacts in reverse order
    // create_mirror (not _view): a real copy even on host backends, where a mirror view aliases.
    auto f = Kokkos::create_mirror(pk.contacts.first), s = Kokkos::create_mirror(pk.contacts.second);
    Kokkos::deep_copy(f, pk.contacts.first);
    Kokkos::deep_copy(s, pk.contacts.second);
    auto f2 = Kokkos::create_mirror_view(pk.contacts.first), s2 = Kokkos::create_mirror_view(pk.contacts.second);
    const int n = pk.contacts.count;
    for (int k = 0; k < n; ++k) {
      f2(k) = f(n - 1 - k);
      s2(k) = s(n - 1 - k);
    }
    Kokkos::deep_copy(pk.contacts.first, f2);
    Kokkos::deep_copy(pk.contacts.second, s2);
  }
  auto model = Model::create({glass()});
  ContactHistory<T, D> h(pk.contacts.count, Model::history_size);
  ContactForceBuffer<T, D> buf;
  ContactIncidence<D> inc;
  if (deterministic) {
    buf = ContactForceBuffer<T, D>(pk.contacts.count);
    inc = build_incidence(pk.particles.n, pk.contacts, pair_contact_keys(pk.particles, pk.contacts), true);
  }
  zero_forces(pk.particles);
  compute_pair_forces(model, pk.particles, pk.contacts, h, T(1e-7), {}, buf);
  if (deterministic) reduce_contact_forces(pk.particles, buf, inc);
  return std::make_pair(test::to_host(pk.particles.force), test::to_host(pk.particles.torque));
}
}  // namespace

TEMPLATE_TEST_CASE("deterministic reduction: same bits for any list order and backend", "[deterministic]", double,
                   float) {
  using T = TestType;
  using DH = test::DeviceOf<Kokkos::DefaultHostExecutionSpace>;
  auto a = forces<T, DH>(true, false);
  auto b = forces<T, DH>(true, true);
  auto atomic = forces<T, DH>(false, false);
  const auto n = a.first.extent(0);
  int diff_bits = 0;
  double fmax = 0, dev = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      // Each contact's terms are the same bits in either list order; the per-particle sums run
      // in key order, so they are the same bits too. (Swapped (j, i) listings, every law, walls
      // and MDR growth: test_deterministic_mode.cpp.)
      diff_bits += a.first(i, d) != b.first(i, d);
      diff_bits += a.second(i, d) != b.second(i, d);
      fmax = std::max(fmax, double(std::abs(a.first(i, d))));
      dev = std::max(dev, double(std::abs(a.first(i, d) - atomic.first(i, d))));
    }
  CHECK(diff_bits == 0);
  REQUIRE(fmax > 0);
  CHECK(dev <= (std::is_same<T, float>::value ? 1e-5 : 1e-12) * fmax);
#if defined(KOKKOS_ENABLE_SERIAL) && defined(KOKKOS_ENABLE_OPENMP)
  auto s = forces<T, test::DeviceOf<Kokkos::Serial>>(true, false);
  auto o = forces<T, test::DeviceOf<Kokkos::OpenMP>>(true, true);
  int diff_backend = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) diff_backend += (s.first(i, d) != o.first(i, d)) + (s.second(i, d) != o.second(i, d));
  CHECK(diff_backend == 0);
#endif
}
