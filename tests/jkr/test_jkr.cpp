// Hertz-JKR baseline (Nan Appendix B): the contact-radius solve at its edges, the force at zero
// overlap (-8/9 f_ce, (B6)), the force-controlled pull-off -1.5 pi Gamma R*, detachment at the
// critical overlap with -5/9 f_ce, hysteresis, Hertz limit, and the stiffness identities (B7)-(B13).
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/models/jkr/jkr.hpp>

#include "../nan2022/overlap_driver.hpp"

#include <cmath>

using namespace epac;

namespace {
Material jkr_particle(double gamma) {
  Material m;
  m.name = "p";
  m.youngs_modulus = 1.2e9;
  m.poisson_ratio = 0.3;
  m.density = 1350;
  m.surface_energy = gamma;
  return m;
}
Material wall() {
  Material m;
  m.name = "wall";
  m.rigid = true;
  return m;
}
constexpr double kR = 2.45e-6;
}  // namespace

TEMPLATE_LIST_TEST_CASE("jkr contact radius: edges of the solve", "[jkr][edge]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double dc = -0.75 * std::cbrt(0.25), xc = std::pow(4.0, -2.0 / 3.0);
  const double ds[] = {dc - 1.0, dc, dc * (1 - 1e-6), -0.3, 0.0, 1e-3, 1.0, 1e2, 1e6};
  const int n = sizeof(ds) / sizeof(ds[0]);
  Kokkos::View<T*, D> in("d", n), out("x", n);
  auto ih = Kokkos::create_mirror_view(in);
  for (int k = 0; k < n; ++k) ih(k) = T(ds[k]);
  Kokkos::deep_copy(in, ih);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, n),
      KOKKOS_LAMBDA(int k) { out(k) = jkr_contact_radius_ratio(in(k)); });
  auto x = test::to_host(out);
  const double tol = sizeof(T) == 4 ? 1e-5 : 1e-11;
  CHECK(jkr_critical_overlap_ratio<double>() == Approx(dc).epsilon(1e-15));
  CHECK(jkr_critical_radius_ratio<double>() == Approx(xc).epsilon(1e-15));
  // At d_c the root is double (g'(x_c) = 0, g'' = 3): a residual of eps |d_c| moves it by
  // sqrt(2 eps |d_c| / 3), so that is the attainable accuracy there.
  const double eps = sizeof(T) == 4 ? 1.2e-7 : 2.2e-16;
  const double tol_c = 4 * std::sqrt(2 * eps / 3);
  CHECK(x(0) == Approx(xc).epsilon(tol));    // below the critical overlap: clamped to the end point
  CHECK(x(1) == Approx(xc).epsilon(tol_c));  // at it
  // just above it the root leaves x_c like sqrt(d - d_c) (double root of g): loose but bounded
  CHECK(x(2) > T(xc) * T(1 - tol));
  CHECK(x(2) < xc * 1.01);
  CHECK(x(4) == Approx(1.0).epsilon(tol));  // (B5): a = a_0 at zero overlap
  for (int k = 2; k < n; ++k) {
    const double xx = x(k);
    INFO("d = " << ds[k] << ", x = " << xx);
    CHECK(xx >= xc * (1 - tol));
    CHECK(xx * xx - std::sqrt(xx) - ds[k] == Approx(0.0).margin(4 * tol * std::max(1.0, std::fabs(ds[k]))));
  }
  CHECK(x(n - 1) == Approx(std::sqrt(1e6)).epsilon(1e-4));  // Hertz-like for deep overlap
}

// The warm-started solve (jkr_contact_radius_root, what the model runs every step) must give the
// closed form's root whatever the guess: near guesses (a step of a moving contact), far ones
// (a restart's contact state 1, a jump in overlap), none, and overlaps at the edges (just above
// d_c, where Newton is ill-conditioned and must hand over to the closed form; beyond 1e6).
TEMPLATE_LIST_TEST_CASE("jkr contact radius: the warm-started root is the closed form's", "[jkr][edge]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double dc = -0.75 * std::cbrt(0.25);
  const double ds[] = {dc * (1 - 1e-6), dc * (1 - 1e-3), -0.3, 0.0, 1e-3, 0.7, 1.0, 30.0, 1e2, 1e4, 1e6, 2e6};
  const double rel[] = {0.0, 1.0, 1 + 1e-7, 1 - 1e-5, 1 + 1e-3, 1 - 0.05, 1.5, 0.5, 10.0};  // guess / root
  const int nd = sizeof(ds) / sizeof(ds[0]), ng = sizeof(rel) / sizeof(rel[0]), n = nd * (ng + 1);
  Kokkos::View<T*, D> d_in("d", n), g_in("guess", n), warm("warm", n), closed("closed", n);
  auto dh = Kokkos::create_mirror_view(d_in);
  auto gh = Kokkos::create_mirror_view(g_in);
  for (int a = 0; a < nd; ++a) {
    const double root = std::sqrt(jkr_contact_radius_ratio(ds[a]));
    for (int b = 0; b <= ng; ++b) {
      dh(a * (ng + 1) + b) = T(ds[a]);
      gh(a * (ng + 1) + b) = b < ng ? T(rel[b] * root) : T(1);  // 1: an old contact-state flag
    }
  }
  Kokkos::deep_copy(d_in, dh);
  Kokkos::deep_copy(g_in, gh);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, n), KOKKOS_LAMBDA(int k) {
        warm(k) = jkr_contact_radius_root(d_in(k), g_in(k));
        closed(k) = math::sqrt(jkr_contact_radius_ratio(d_in(k)));
      });
  auto w = test::to_host(warm);
  auto c = test::to_host(closed);
  // Both are roots to round-off: the closed form is polished by a Newton step, the warm start
  // accepted when its next correction is below 2 eps y, so they differ by a few ulps, except
  // within ~sqrt(eps) of d_c, where the root itself is only that accurate (the double root of
  // the edge test above) and the warm start hands over to the closed form.
  const double eps = sizeof(T) == 4 ? 1.2e-7 : 2.2e-16;
  for (int k = 0; k < n; ++k) {
    INFO("d = " << dh(k) << ", guess = " << gh(k) << ", warm = " << w(k) << ", closed = " << c(k));
    const double y = w(k), d = dh(k);
    CHECK(y == Approx(c(k)).epsilon(16 * eps));
    CHECK(y * y * y * y - y - d == Approx(0.0).margin(16 * eps * std::max(1.0, std::fabs(d))));
    CHECK(y * y >= jkr_critical_radius_ratio<double>() * (1 - 4 * eps));
  }
}

TEMPLATE_LIST_TEST_CASE("jkr loop: -8/9 f_ce at zero overlap, pull-off -1.5 pi Gamma R*, detachment at delta_c",
                        "[jkr]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = Jkr<T, Effects<kAdhesion | kFriction | kDamping>, D>;
  const double G = 0.2;
  const Model model = Model::create({jkr_particle(G), wall()});
  const double E = 1.2e9 / 0.91;
  const double f_ce = 1.5 * M_PI * G * kR;
  const double delta_c = -0.75 * std::cbrt(M_PI * M_PI * G * G * kR / (E * E));
  const double step = std::fabs(delta_c) / 5000;
  std::vector<double> a{-0.5 * std::fabs(delta_c)};
  test::ramp(a, 0.0, step);
  const std::size_t k0 = a.size() - 1;
  test::ramp(a, 3 * std::fabs(delta_c), step);
  test::ramp(a, 1.2 * delta_c, step);
  test::ramp(a, 0.5 * std::fabs(delta_c), step);
  const auto t = test::drive_overlap(model, a, kR, 1);
  const double tol = (sizeof(T) == 4 ? 1e-4 : 1e-9) * f_ce;
  for (std::size_t k = 0; k < k0; ++k) CHECK(t.active[k] == 0);
  CHECK(t.active[k0] == 1);
  CHECK(t.f[k0] == Approx(-8.0 / 9.0 * f_ce).margin(tol));  // (B6)
  double fmin = 0;
  for (double f : t.f) fmin = std::min(fmin, f);
  CHECK(fmin == Approx(-f_ce).epsilon(1e-4));  // force-controlled pull-off, -1.5 pi Gamma R*
  // detachment at delta_c with -5/9 f_ce; re-contact only at delta >= 0
  std::size_t kd = k0;
  while (kd < t.size() && t.active[kd]) ++kd;
  REQUIRE(kd < t.size());
  CHECK(t.alpha[kd - 1] >= delta_c * (1 + 1e-5));
  CHECK(t.alpha[kd] < delta_c * (1 - 1e-5));
  // Near delta_c the tangent df/d(delta) is infinite: x - x_c ~ sqrt(2 (d - d_c)/3) (g'' = 3 at
  // x_c) and df/dx = -1.68 f_ce there, so the last sample sits within that of -5/9 f_ce, and it
  // is the force of the JKR curve at its overlap.
  const auto sc = jkr_scales(G, kR, E);
  const double d_last = t.alpha[kd - 1] / sc.delta_s;
  CHECK(t.f[kd - 1] == Approx(f_ce * jkr_force_ratio(jkr_contact_radius_ratio(d_last))).epsilon(1e-4));
  const double eps = sizeof(T) == 4 ? 1.2e-7 : 2.2e-16;  // d is rounded to T on the device
  const double dd = std::max(d_last - jkr_critical_overlap_ratio<double>(), 4 * eps);
  const double bound = 1.7 * f_ce * std::sqrt(2 * dd / 3);
  CHECK(t.f[kd - 1] <= -5.0 / 9.0 * f_ce);
  CHECK(t.f[kd - 1] >= -5.0 / 9.0 * f_ce - bound * 1.1 - tol);
  std::size_t kr = kd;
  while (kr < t.size() && !t.active[kr]) ++kr;
  REQUIRE(kr < t.size());
  CHECK(t.alpha[kr] >= 0.0);
  CHECK(t.alpha[kr - 1] < 0.0);
  // stiffness and tangential stiffness: 2 E* a and 8 G* a
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!t.active[k]) continue;
    CHECK(t.k_n[k] > 0);
    CHECK(t.k_t[k] == Approx(t.k_n[k] * 4 * (1.2e9 / 2.6 / 1.7) / E).epsilon(1e-5));
  }
}

TEMPLATE_LIST_TEST_CASE("jkr without adhesion is Hertz", "[jkr][edge]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double E = 1.2e9 / 0.91;
  std::vector<double> a{-1e-8};
  test::ramp(a, 1e-7, 1e-9);
  for (int variant = 0; variant < 2; ++variant) {
    test::OverlapTrace t;
    if (variant == 0) {
      using Model = Jkr<T, Effects<kAdhesion>, D>;
      t = test::drive_overlap(Model::create({jkr_particle(0.0), wall()}), a, kR, 1);
    } else {
      using Model = Jkr<T, Effects<0>, D>;
      static_assert(Model::history_size == 0, "no adhesion, no friction: no history");
      t = test::drive_overlap(Model::create({jkr_particle(0.2), wall()}), a, kR, 1);
    }
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double d = t.alpha[k];
      const double f = d > 0 ? 4.0 / 3.0 * E * std::sqrt(kR) * std::pow(d, 1.5) : 0.0;
      CHECK(t.f[k] == Approx(f).epsilon(1e-5).margin(1e-12));
      CHECK(t.active[k] == (d > 0 ? 1 : 0));
    }
  }
}

TEST_CASE("jkr stiffness identities of Nan Appendix B, (B7)-(B13)", "[jkr]") {
  const double G = 0.2, R = kR, E = 1.3e9;
  const auto s = jkr_scales(G, R, E);
  const double c = std::cbrt(G * E * E * R * R);
  // (B7) = (40): k at delta = 0 is (16 pi/27)^(1/3) (Gamma E*^2 R*^2)^(1/3) = 1.23 (...)
  CHECK(jkr_tangent_stiffness(1.0, s.a0, E) == Approx(std::cbrt(16 * M_PI / 27) * c).epsilon(1e-12));
  CHECK(std::cbrt(16 * M_PI / 27) == Approx(1.23).margin(0.005));
  // f = 0 at x^(3/2) = 3/2 (B8)-(B9): f_H/f_ce = 4; (B10) and (B11)
  const double x0 = std::cbrt(2.25);
  CHECK(jkr_force_ratio(x0) == Approx(0.0).margin(1e-14));
  CHECK(x0 * s.a0 == Approx(std::cbrt(9 * M_PI * G * R * R / (2 * E))).epsilon(1e-12));
  const double kb10 = 1.2 * std::cbrt(4.5) * std::cbrt(M_PI) * c;
  CHECK(jkr_tangent_stiffness(x0, s.a0, E) == Approx(kb10).epsilon(1e-12));
  const double alpha0 = (x0 * x0 - std::sqrt(x0)) * s.delta_s;
  CHECK(alpha0 == Approx(std::cbrt(0.75) * std::cbrt(M_PI * M_PI * R * G * G / (E * E))).epsilon(1e-12));
  // (B12)-(B13): JKR tangent / Hertz stiffness at the same overlap = 3 sqrt(3)/5 = 1.04
  const double kH = 2 * E * std::sqrt(R * alpha0);
  CHECK(jkr_tangent_stiffness(x0, s.a0, E) / kH == Approx(3 * std::sqrt(3.0) / 5).epsilon(1e-12));
  // pull-off point (force-controlled) and critical point (displacement-controlled)
  CHECK(jkr_force_ratio(std::pow(0.75, 2.0 / 3.0)) == Approx(-1.0).epsilon(1e-14));
  CHECK(jkr_force_ratio(jkr_critical_radius_ratio<double>()) == Approx(-5.0 / 9.0).epsilon(1e-14));
  CHECK(jkr_tangent_stiffness(std::pow(0.75, 2.0 / 3.0), s.a0, E) == Approx(0.0).margin(1e-9 * c));
}
