// Conservation in an isolated collision: linear and angular momentum to round-off (with friction
// and damping), kinetic energy to the integrator's accuracy without damping.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/models/hertz_mindlin.hpp>

#include "verlet_stepper.hpp"

#include <cmath>

using namespace epac;

namespace {
Material glass(double e0, double mu) {
  Material m;
  m.name = "glass";
  m.youngs_modulus = 70e9;
  m.poisson_ratio = 0.25;
  m.density = 2500;
  m.restitution = e0;
  m.friction = mu;
  return m;
}
struct Totals {
  double p[3], L[3], ke;
};
template <class P>
Totals totals(const P& p) {
  auto x = test::to_host(p.x);
  auto v = test::to_host(p.v);
  auto w = test::to_host(p.omega);
  auto m = test::to_host(p.mass);
  auto I = test::to_host(p.inertia);
  Totals t{{0, 0, 0}, {0, 0, 0}, 0};
  for (int i = 0; i < p.n; ++i) {
    for (int d = 0; d < 3; ++d) {
      t.p[d] += m(i) * v(i, d);
      const int a = (d + 1) % 3, b = (d + 2) % 3;
      t.L[d] += m(i) * (x(i, a) * v(i, b) - x(i, b) * v(i, a)) + I(i) * w(i, d);
      t.ke += 0.5 * m(i) * v(i, d) * v(i, d) + 0.5 * I(i) * w(i, d) * w(i, d);
    }
  }
  return t;
}
// Hertz contact duration for two equal spheres (Johnson): 2.87 (m*^2 / (R* E*^2 v))^(1/5).
double hertz_duration(double m_eff, double R_eff, double E_star, double v) {
  return 2.87 * std::pow(m_eff * m_eff / (R_eff * E_star * E_star * v), 0.2);
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("oblique collision with friction and damping conserves momentum", "[conservation]",
                        test::Backends) {
  using D = TestType;
  using Model = HertzMindlin<double, Effects<kFriction | kDamping>, D>;
  const double R = 1e-3, m = 2500 * 4.0 / 3.0 * M_PI * R * R * R, v0 = 0.5;
  // Centres offset by R across the line of approach; surfaces 1e-7 m apart along the line.
  const double gap = std::sqrt((2 * R + 1e-7) * (2 * R + 1e-7) - R * R) - 2 * R;
  test::VerletStepper<Model, double, D> s{Model::create({glass(0.6, 0.5)}),
                                          test::two_spheres<double, D>(R, m, v0, gap, 1.0 * R)};
  s.pairs = test::single_pair<D>();
  s.pair_hist = ContactHistory<double, D>(1, Model::history_size);
  const double E_star = 70e9 / (2 * (1 - 0.0625));
  s.dt = hertz_duration(m / 2, R / 2, E_star, v0) / 400;
  const Totals before = totals(s.p);
  s.start();
  double max_ft = 0;
  for (int k = 0; k < 2000; ++k) {
    s.step();
    auto t = test::to_host(s.p.torque);
    max_ft = std::max(max_ft, std::abs(t(0, 2)));
  }
  const Totals after = totals(s.p);
  REQUIRE(max_ft > 0);                  // friction acted
  REQUIRE(after.ke < 0.9 * before.ke);  // damping and friction dissipated energy
  const double pscale = m * v0, Lscale = m * v0 * R;
  for (int d = 0; d < 3; ++d) {
    CHECK(std::abs(after.p[d] - before.p[d]) <= 1e-12 * pscale);
    CHECK(std::abs(after.L[d] - before.L[d]) <= 1e-11 * Lscale);
  }
}

TEMPLATE_LIST_TEST_CASE("undamped frictionless Hertz collision conserves kinetic energy", "[conservation]",
                        test::Backends) {
  using D = TestType;
  using Model = HertzMindlin<double, Effects<0>, D>;
  const double R = 1e-3, m = 2500 * 4.0 / 3.0 * M_PI * R * R * R, v0 = 1.0;
  test::VerletStepper<Model, double, D> s{Model::create({glass(1.0, 0.0)}),
                                          test::two_spheres<double, D>(R, m, v0, 1e-9)};
  s.pairs = test::single_pair<D>();
  const double E_star = 70e9 / (2 * (1 - 0.0625));
  const double tc = hertz_duration(m / 2, R / 2, E_star, v0);
  s.dt = tc / 200;
  const Totals before = totals(s.p);
  s.start();
  for (int k = 0; k < 400; ++k) s.step();
  const Totals after = totals(s.p);
  // Velocity Verlet's energy error over one Hertz contact at tc/dt = 200 is O((dt/tc)^2) ~ 1e-5;
  // 1e-4 leaves a margin of ten and still catches any missing or double-counted force.
  CHECK(after.ke == Approx(before.ke).epsilon(1e-4));
  auto v = test::to_host(s.p.v);
  CHECK(v(1, 0) - v(0, 0) == Approx(v0).epsilon(1e-4));  // the spheres separated
}
