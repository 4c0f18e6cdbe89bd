// Hertz force and stiffness against the closed form, for pairs and walls, every backend,
// double and float; Newton's third law per contact.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/hertz_mindlin.hpp>

#include "verlet_stepper.hpp"

#include <cmath>

using namespace epac;

namespace {
Material glass() {
  Material m;
  m.name = "glass";
  m.youngs_modulus = 70e9;
  m.poisson_ratio = 0.25;
  m.density = 2500;
  m.restitution = 0.7;
  m.friction = 0.4;
  return m;
}
template <class T>
double tol() {
  return std::is_same<T, float>::value ? 2e-5 : 1e-12;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("Hertz pair force equals (4/3) E* sqrt(R*) delta^1.5", "[hertz]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const Material g = glass();
  auto model = HertzMindlin<T, Effects<0>, D>::create({g});
  const double R = 1e-3, m = 1e-5;
  const double E_star = g.youngs_modulus / (2 * (1 - g.poisson_ratio * g.poisson_ratio));
  for (double delta : {1e-8, 1e-6, 1e-5, 5e-5}) {
    auto p = test::two_spheres<T, D>(R, m, 0.0, -delta);
    auto c = test::single_pair<D>();
    ContactHistory<T, D> h(1, 0);
    zero_forces(p);
    compute_pair_forces(model, p, c, h, T(1e-7));
    auto f = test::to_host(p.force);
    const double expect = 4.0 / 3.0 * E_star * std::sqrt(R / 2) * std::pow(delta, 1.5);
    // Particle 0 sits at -x: it is pushed along -x, particle 1 along +x.
    const double rel = std::is_same<T, float>::value ? 1e-3 * (1e-6 / std::min(delta, 1e-6)) : 1e-9;
    CHECK(-f(0, 0) == Approx(expect).epsilon(rel));
    CHECK(f(1, 0) == -f(0, 0));  // Newton's third law, bit for bit
    CHECK(f(0, 1) == T(0));
  }
}

TEMPLATE_LIST_TEST_CASE("Hertz stiffness is dF/d(delta) and the wall force uses R* = R", "[hertz]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  Material wall;
  wall.name = "steel";
  wall.rigid = true;
  auto model = HertzMindlin<T, Effects<0>, D>::create({glass(), wall});
  Kokkos::View<double*, D> out("out", 4);
  const double R = 2e-3, d0 = 1e-5;
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        ContactGeometry<T> g;
        g.R_eff = T(R);
        g.pair = 1;  // glass against rigid wall
        HistoryRow<T, D> row{{}, 0, 0};
        const T h = T(d0 * 1e-3);
        g.delta = T(d0);
        const auto n0 = model.normal(g, row);
        g.delta = T(d0) + h;
        const auto np = model.normal(g, row);
        g.delta = T(d0) - h;
        const auto nm = model.normal(g, row);
        out(0) = double(n0.f);
        out(1) = double(n0.k_n);
        out(2) = double((np.f - nm.f) / (T(2) * h));
        g.delta = T(0);
        out(3) = double(model.normal(g, row).active ? 1 : 0);
      });
  auto o = test::to_host(out);
  const Material gl = glass();
  const double E_star = gl.youngs_modulus / (1 - gl.poisson_ratio * gl.poisson_ratio);  // rigid wall
  CHECK(o(0) == Approx(4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(d0, 1.5)).epsilon(tol<T>() * 10));
  CHECK(o(1) == Approx(2.0 * E_star * std::sqrt(R * d0)).epsilon(tol<T>() * 10));
  // central difference: O(h^2) = 1e-7 relative in double; float loses ~3 digits to cancellation
  CHECK(o(2) == Approx(o(1)).epsilon(std::is_same<T, float>::value ? 5e-2 : 1e-6));
  CHECK(o(3) == 0);  // touching without overlap: no contact
}

TEMPLATE_LIST_TEST_CASE("Newton's third law per contact with friction and spin", "[hertz][newton]", test::Backends) {
  using D = TestType;
  using T = double;
  auto model = HertzMindlin<T, Effects<kFriction | kDamping>, D>::create({glass()});
  auto p = test::two_spheres<T, D>(1e-3, 1e-5, 0.3, -2e-6, 1e-5);
  {
    auto w = Kokkos::create_mirror_view(p.omega);
    auto v = Kokkos::create_mirror_view(p.v);
    Kokkos::deep_copy(v, p.v);
    w(0, 0) = 3;
    w(0, 1) = -2;
    w(0, 2) = 5;
    w(1, 0) = -1;
    w(1, 1) = 4;
    w(1, 2) = 0.5;
    v(0, 2) = 0.05;
    Kokkos::deep_copy(p.omega, w);
    Kokkos::deep_copy(p.v, v);
  }
  auto c = test::single_pair<D>();
  ContactHistory<T, D> h(1, decltype(model)::history_size);
  zero_forces(p);
  for (int s = 0; s < 5; ++s) {  // grow a tangential history
    zero_forces(p);
    compute_pair_forces(model, p, c, h, 1e-7);
  }
  auto f = test::to_host(p.force);
  auto t = test::to_host(p.torque);
  auto x = test::to_host(p.x);
  for (int d = 0; d < 3; ++d) CHECK(f(0, d) == -f(1, d));
  REQUIRE(std::abs(f(0, 1)) + std::abs(f(0, 2)) > 0);  // tangential force present
  // Angular momentum balance: the pair acts at one contact point, so x0 x F0 + x1 x F1 + t0 + t1 = 0.
  auto crs = [&](int i, int d) {
    const int a = (d + 1) % 3, b = (d + 2) % 3;
    return x(i, a) * f(i, b) - x(i, b) * f(i, a);
  };
  double scale = 0;
  for (int d = 0; d < 3; ++d) scale = std::max(scale, std::abs(t(0, d)) + std::abs(crs(0, d)));
  for (int d = 0; d < 3; ++d) CHECK(std::abs(crs(0, d) + crs(1, d) + t(0, d) + t(1, d)) <= 1e-12 * scale);
}
