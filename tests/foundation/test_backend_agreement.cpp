// OpenMP equals Serial on a dense packing with more than 10k contacts. The only difference is
// the order of the atomic additions (at most 7 terms per particle), so the per-particle forces
// agree to a few ulps of the largest term: 1e-12 relative in double, 1e-5 in float.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <support/dense_packing.hpp>

#include "../foundation/verlet_stepper.hpp"

using namespace epac;

#if defined(KOKKOS_ENABLE_SERIAL) && defined(KOKKOS_ENABLE_OPENMP)
TEMPLATE_TEST_CASE("OpenMP and Serial give the same forces on a 10k-contact packing", "[backends]", double, float) {
  using T = TestType;
  using DS = test::DeviceOf<Kokkos::Serial>;
  using DO = test::DeviceOf<Kokkos::OpenMP>;
  Material m;
  m.name = "glass";
  m.youngs_modulus = 70e9;
  m.poisson_ratio = 0.25;
  m.density = 2500;
  m.restitution = 0.5;
  m.friction = 0.5;
  auto run = [&](auto dev) {
    using D = decltype(dev);
    using Model = HertzMindlin<T, Effects<kFriction | kDamping>, D>;
    auto pk = bench::make_dense_packing<T, D>(18);
    ContactHistory<T, D> h(pk.contacts.count, Model::history_size);
    auto model = Model::create({m});
    for (int s = 0; s < 5; ++s) {  // several passes: tangential history builds up
      zero_forces(pk.particles);
      compute_pair_forces(model, pk.particles, pk.contacts, h, T(1e-7));
    }
    return std::make_pair(test::to_host(pk.particles.force), pk.contacts.count);
  };
  auto [fs, nc] = run(DS{});
  auto [fo, nc2] = run(DO{});
  REQUIRE(nc >= 10000);
  REQUIRE(nc == nc2);
  double fmax = 0, diff = 0;
  for (std::size_t i = 0; i < fs.extent(0); ++i)
    for (int d = 0; d < 3; ++d) {
      fmax = std::max(fmax, double(std::abs(fs(i, d))));
      diff = std::max(diff, double(std::abs(fs(i, d) - fo(i, d))));
    }
  REQUIRE(fmax > 0);
  CHECK(diff <= (std::is_same<T, float>::value ? 1e-5 : 1e-12) * fmax);
}
#endif
