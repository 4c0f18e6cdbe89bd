// Head-on collisions with damping set from e0 rebound with e0: exactly for the linear spring
// (Nan (24)-(26)), and for Hertz through the exact relation of params/restitution_damping.hpp,
// at any impact speed.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/linear_spring.hpp>

#include "verlet_stepper.hpp"

#include <cmath>

using namespace epac;

namespace {
Material mat(double e0) {
  Material m;
  m.name = "m";
  m.youngs_modulus = 1e8;
  m.poisson_ratio = 0.3;
  m.density = 2000;
  m.restitution = e0;
  return m;
}
template <class Model, class D>
double measured_restitution(const Model& model, double v0, double dt) {
  const double R = 1e-3, m = 2000 * 4.0 / 3.0 * M_PI * R * R * R;
  test::VerletStepper<Model, double, D> s{model, test::two_spheres<double, D>(R, m, v0, 0.0)};
  s.pairs = test::single_pair<D>();
  s.dt = dt;
  s.start();
  for (int k = 0; k < 100000; ++k) {
    s.step();
    auto x = test::to_host(s.p.x);
    if (k > 2 && x(1, 0) - x(0, 0) > 2 * R) break;  // separated
  }
  auto v = test::to_host(s.p.v);
  return (v(1, 0) - v(0, 0)) / v0;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("linear spring rebounds with e0 within 1%", "[restitution]", test::Backends) {
  using D = TestType;
  using Model = LinearSpring<double, Effects<kDamping>, D>;
  const double k = 1e4, m_eff = 0.5 * 2000 * 4.0 / 3.0 * M_PI * 1e-9;
  const double tc = M_PI * std::sqrt(m_eff / k);
  for (double e0 : {0.1, 0.5, 0.81, 0.95}) {
    const double e = measured_restitution<Model, D>(Model::create({mat(e0)}, k), 0.2, tc / 1000);
    CHECK(e == Approx(e0).epsilon(0.01));
  }
}

TEST_CASE("Hertz damping coefficient: e(c) monotone, inverse exact, ends handled", "[restitution]") {
  CHECK(hertz_damping_coefficient(1.0) == 0.0);
  CHECK(hertz_restitution_for(0.0) == Approx(1.0).epsilon(1e-6));
  double prev = 1.0;
  for (double c = 0.1; c < 3; c += 0.3) {
    const double e = hertz_restitution_for(c);
    CHECK(e < prev);
    prev = e;
  }
  for (double e0 : {0.2, 0.5, 0.9})
    CHECK(hertz_restitution_for(hertz_damping_coefficient(e0)) == Approx(e0).epsilon(1e-6));
  CHECK(std::isfinite(hertz_damping_coefficient(0.0)));
  CHECK(linear_damping_ratio(0.0) == 1.0);  // ln(0) guarded: the critical-damping limit
  CHECK_THROWS_AS(hertz_damping_coefficient(1.5), ParameterError);
}

TEMPLATE_LIST_TEST_CASE("Hertz rebounds with e0 within 1% at any impact speed", "[restitution]", test::Backends) {
  using D = TestType;
  using Model = HertzMindlin<double, Effects<kDamping>, D>;
  const double R = 1e-3, m = 2000 * 4.0 / 3.0 * M_PI * R * R * R;
  const double E_star = 1e8 / (2 * (1 - 0.09));
  for (double e0 : {0.3, 0.7, 0.9}) {
    for (double v0 : {0.05, 2.0}) {
      const double tc = 2.87 * std::pow((m / 2) * (m / 2) / ((R / 2) * E_star * E_star * v0), 0.2);
      const double e = measured_restitution<Model, D>(Model::create({mat(e0)}), v0, tc / 1000);
      CHECK(e == Approx(e0).epsilon(0.01));
    }
  }
}
