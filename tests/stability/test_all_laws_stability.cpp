// Numerical stability across every law (docs/stability.md): hard cases stay finite and create no
// energy.
//   - a sweep of radii (1e-7 .. 1e-1 m), stiffness (E = 1e6 .. 1e12 Pa, E/Y up to 1e4), overlaps
//     from 1e-9 R to 0.9 R and small negative gaps, with and without adhesion, in double and
//     float, wall and pair contacts, with large random velocities: every force finite;
//   - a contact driven through load / unload / reload cycles to separation returns at most the
//     work put in (W_net = integral of F d(delta) over the closed path >= 0, to round-off).
// Each law is driven through the contact kernel itself (compute_wall_forces / compute_pair_forces).
#include "stability_helpers.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace epac;
using namespace epac::test;

namespace {
Material mat(double E, double Y, double gamma, double R) { return stability_material(E, Y, gamma, R); }
Material rigid() { return stability_wall(); }

// One sphere of radius R against wall 0 (plane z = 0) and a second sphere (pair), both at
// overlap delta; returns the two z-forces on the first sphere.
template <class Model>
struct Probe {
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;
  Model model;
  Particles<T, D> p{3, "probe"};
  Walls<T, D> w{1, "probe_wall"};
  ContactList<D> wc{1, "probe_wc"}, pc{1, "probe_pc"};
  ContactHistory<T, D> wh, ph;
  double R;
  Probe(const Model& m, double radius, double mass)
      : model(m), wh(1, Model::history_size), ph(1, Model::history_size), R(radius) {
    Kokkos::deep_copy(p.radius, T(R));
    Kokkos::deep_copy(p.radius0, T(R));
    Kokkos::deep_copy(p.mass, T(mass));
    Kokkos::deep_copy(p.inertia, T(0.4 * mass * R * R));
    Kokkos::deep_copy(p.material, 0);
    auto g = Kokkos::create_mirror_view(p.gid);
    g(0) = 0;
    g(1) = 1;
    g(2) = 2;
    Kokkos::deep_copy(p.gid, g);
    auto n = Kokkos::create_mirror_view(w.normal);
    Kokkos::deep_copy(n, T(0));
    n(0, 2) = T(1);
    Kokkos::deep_copy(w.normal, n);
    Kokkos::deep_copy(w.material, 1);
    Kokkos::deep_copy(wc.first, 0);
    Kokkos::deep_copy(wc.second, 0);
    auto f = Kokkos::create_mirror_view(pc.first);
    f(0) = 1;
    Kokkos::deep_copy(pc.first, f);
    auto s = Kokkos::create_mirror_view(pc.second);
    s(0) = 2;
    Kokkos::deep_copy(pc.second, s);
  }
  // wall force on sphere 0 and pair force on sphere 1 (pair overlap 2 delta: delta per sphere)
  std::pair<double, double> at(double delta, double vz, double dt) {
    auto x = Kokkos::create_mirror_view(p.x);  // double positions: a declaration of its own
    auto v = Kokkos::create_mirror_view(p.v);
    Kokkos::deep_copy(x, T(0));
    Kokkos::deep_copy(v, T(0));
    x(0, 2) = T(R - delta);
    v(0, 2) = T(vz);
    v(0, 0) = T(0.3 * vz);  // sliding as well
    x(1, 2) = T(0);
    x(2, 2) = T(2 * R - 2 * delta);
    v(1, 2) = T(-vz);
    v(1, 1) = T(0.2 * vz);
    Kokkos::deep_copy(p.x, x);
    Kokkos::deep_copy(p.v, v);
    zero_forces(p);
    compute_wall_forces(model, p, w, wc, wh, T(dt));
    compute_pair_forces(model, p, pc, ph, T(dt));
    if constexpr (Model::effects::radius_growth) model.update_radii();
    auto F = test::to_host(p.force);
    return {double(F(0, 2)), -double(F(1, 2))};
  }
};

template <template <class> class Make, class T>
void sweep_finite() {
  int checked = 0, bad = 0;
  for (double R : {1e-7, 1e-4, 1e-1})
    for (double E : {1e6, 1e12})
      for (double EY : {6.25, 1e4})
        for (double gamma : {0.0, 1e-3}) {
          const Material m = mat(E, E / EY, gamma, R);
          Probe<typename Make<T>::M> probe(Make<T>::make({m, rigid()}), R, 2500 * 4.19 * R * R * R);
          const double vmax = 10.0;
          std::vector<double> path;                                          // host
          for (double d = 1e-9; d < 0.9; d *= 1.6) path.push_back(d * R);    // load to 0.9 R
          for (double d = 0.9; d > -0.05; d -= 0.05) path.push_back(d * R);  // unload past contact
          for (double d = -1e-3; d < 0.5; d += 0.05) path.push_back(d * R);  // reload
          double prev = 0;
          for (double delta : path) {
            const double vz = (delta > prev ? -vmax : vmax);
            const auto f = probe.at(delta, vz, 1e-9);
            ++checked;
            if (!std::isfinite(f.first) || !std::isfinite(f.second)) {
              ++bad;
              UNSCOPED_INFO("non-finite at R=" << R << " E=" << E << " E/Y=" << EY << " gamma=" << gamma
                                               << " delta/R=" << delta / R);
            }
            prev = delta;
          }
        }
  CHECK(checked > 1000);
  CHECK(bad == 0);
}

// Quasi-static closed cycles: approach from a gap, load, unload to a partial overlap, reload
// past the old maximum, unload to full separation, back to the start. Work done on the
// contact W = integral F d(delta) (trapezoid on a fine path) must be >= 0: a law may dissipate,
// never create. Damping off (no velocity), friction irrelevant (no sliding).
template <template <class> class Make, class T>
void cycle_creates_no_energy() {
  for (double EY : {6.25, 50.0, 1e3})
    for (double gamma : {0.0, 2e-5}) {
      const double R = 1e-5, E = 1e9;
      const Material m = mat(E, E / EY, gamma, R);
      Probe<typename Make<T>::M> probe(Make<T>::make({m, rigid()}), R, 2500 * 4.19 * R * R * R);
      std::vector<double> path;  // host, in units of R
      auto ramp = [&](double a, double b, int n) {
        for (int k = 1; k <= n; ++k) path.push_back(a + (b - a) * k / n);
      };
      path.push_back(-0.01);
      ramp(-0.01, 0.05, 3000);
      ramp(0.05, 0.02, 3000);
      ramp(0.02, 0.10, 3000);
      ramp(0.10, -0.01, 6000);
      double W_wall = 0, W_pair = 0, d_prev = -0.01 * R;
      auto f_prev = probe.at(d_prev, 0, 1e-9);
      double scale = 0;
      for (std::size_t k = 1; k < path.size(); ++k) {
        const double d = path[k] * R;
        const auto f = probe.at(d, 0, 1e-9);
        W_wall += 0.5 * (f.first + f_prev.first) * (d - d_prev);
        W_pair += 0.5 * (f.second + f_prev.second) * (2 * (d - d_prev));
        scale = std::max(scale, std::abs(f.first) * 0.1 * R);
        f_prev = f;
        d_prev = d;
      }
      INFO("E/Y = " << EY << ", gamma = " << gamma << ", W_wall = " << W_wall << ", W_pair = " << W_pair
                    << ", scale = " << scale);
      REQUIRE(scale > 0);
      // Trapezoid error on 3000-point ramps plus float round-off: 1e-3 of F_max * 0.1 R.
      const double tol = (std::is_same<T, float>::value ? 1e-2 : 1e-3) * scale;
      CHECK(W_wall >= -tol);
      CHECK(W_pair >= -tol);
    }
}
}  // namespace

TEMPLATE_TEST_CASE("every law stays finite over the hard-case sweep", "[stability]", double, float) {
  SECTION("hertz_mindlin") { sweep_finite<MakeHM, TestType>(); }
  SECTION("hertz_jkr") { sweep_finite<MakeJkr, TestType>(); }
  SECTION("nan2022") { sweep_finite<MakeNan, TestType>(); }
  SECTION("mdr") { sweep_finite<MakeMdr, TestType>(); }
}

TEMPLATE_TEST_CASE("no law returns more work than was put in over closed cycles", "[stability][energy]", double,
                   float) {
  SECTION("hertz_mindlin") { cycle_creates_no_energy<MakeHM, TestType>(); }
  SECTION("hertz_jkr") { cycle_creates_no_energy<MakeJkr, TestType>(); }
  SECTION("nan2022") { cycle_creates_no_energy<MakeNan, TestType>(); }
  SECTION("mdr") { cycle_creates_no_energy<MakeMdr, TestType>(); }
}
