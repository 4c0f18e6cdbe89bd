// MDR adhesion: JKR in the elastic regime, pull-off forces for both control modes, increment
// convergence, critical radius and peeling root at their edges, re-forming after compression.
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace epac;
using namespace epac::test;

namespace {

// load to dmax, unload to -dneg in n steps each
std::vector<double> load_unload(double dmax, double dneg, int n_load, int n_unload) {
  std::vector<double> p;
  append_ramp(p, 0.0, dmax, n_load);
  append_ramp(p, dmax, -dneg, n_unload);
  return p;
}

double max_tension(const SideTrace& t) {
  double m = 0.0;
  for (double f : t.F) m = std::max(m, -f);
  return m;
}
int separation_step(const SideTrace& t) {
  for (int k = 0; k < t.size(); ++k)
    if (t.state[k] == kMdrSeparated) return k;
  return -1;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("MDR adhesion, elastic: JKR once the edge springs reach Delta l; pull-off forces",
                        "[mdr][adhesion][jkr]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double E = 1.0, R = 1.0, Eeff = E / (1 - kNu * kNu);
  const double gamma = Eeff * R / 2.2e4;  // E* R / Delta gamma = 2.2e4 (Fig. 13(a))
  const Jkr jkr{Eeff, R, gamma};
  const auto c = side_constants<T>(E, kNu, kInf);
  const double dmax = 4e-3 * R;  // elastic, a_max = 0.063 R
  for (int xi : {1, 3}) {
    const std::vector<double> path = load_unload(dmax, 0.01 * R, 200, 4000);
    const SideTrace t = run_side_path<D, T, true, true>(c, gamma, xi, R, path);
    INFO("xi = " << xi);
    // loading: non-adhesive (Hertz up to the ellipse's 0.075 delta/R)
    CHECK(t.F[199] == Approx(4.0 / 3.0 * Eeff * std::sqrt(R) * std::pow(dmax, 1.5)).epsilon(1e-3));
    const int sep = separation_step(t);
    REQUIRE(sep > 200);
    int peeling = 0;
    for (int k = 200; k < sep; ++k) {
      if (t.state[k] != kMdrPeeling) continue;
      ++peeling;
      const double Fj = jkr.force_of_delta(path[k]);
      // 1% of the force scale (max(|F_JKR|, F_c)): the force crosses zero on this branch
      CHECK(std::fabs(t.F[k] - Fj) < 0.01 * std::max(std::fabs(Fj), jkr.pull_off()));
    }
    CHECK(peeling > 100);
    // pull-off (largest tension, Appendix F.2): 3/2 pi gamma R for both modes
    CHECK(max_tension(t) == Approx(jkr.pull_off()).epsilon(0.01));
    // the last tension before separation is the control mode's JKR value:
    // xi = 3: separation at the force-control instability, -3/2 pi gamma R;
    // xi = 1: at the displacement-control instability, -5/6 pi gamma R (approached like sqrt(step))
    const double last = -t.F[sep - 1];
    if (xi == 3) {
      CHECK(last == Approx(jkr.pull_off()).epsilon(0.01));
    } else {
      // the last tension approaches 5/6 pi gamma R like sqrt(step): 4x finer steps halve the excess
      const SideTrace t4 = run_side_path<D, T, true, true>(c, gamma, xi, R, load_unload(dmax, 0.01 * R, 200, 16000));
      const int sep4 = separation_step(t4);
      REQUIRE(sep4 > 0);
      const double last4 = -t4.F[sep4 - 1];
      const double target = jkr.pull_off_displacement_control();
      CHECK(last > target * (1 - 5e-3));
      CHECK(last4 > target * (1 - 5e-3));
      CHECK(last4 - target < 0.65 * (last - target) + 2e-3 * target);
      CHECK(last4 == Approx(target).epsilon(0.03));
    }
    // after separation: no force, no adhesive radius, until pressed again
    for (int k = sep; k < t.size(); ++k) {
      CHECK(t.F[k] == 0.0);
      CHECK(t.a[k] == 0.0);
    }
  }
}

TEMPLATE_LIST_TEST_CASE("MDR adhesion: re-forms only after compression; states follow the paper's rule",
                        "[mdr][adhesion]", Backends) {
  using D = TestType;
  using T = double;
  const double E = 1.0, R = 1.0, Eeff = E / (1 - kNu * kNu);
  const double gamma = Eeff * R / 2.2e4;
  const auto c = side_constants<T>(E, kNu, E / 12.5);
  std::vector<double> path;
  append_ramp(path, 0.0, 0.2 * R, 400);  // plastic loading (delta_Y = 0.12 R)
  const int n1 = static_cast<int>(path.size());
  append_ramp(path, 0.2 * R, -0.02 * R, 4000);  // unload through separation
  const int n2 = static_cast<int>(path.size());
  append_ramp(path, -0.02 * R, 0.2 * R, 400);   // press again
  append_ramp(path, 0.2 * R, -0.02 * R, 4000);  // and pull off again
  const SideTrace t = run_side_path<D, T, true, true>(c, gamma, 1, R, path);
  REQUIRE(t.yielded[n1 - 1] == 1);
  // loading: no tension, a = B/2 = a_max
  for (int k = 10; k < n1; ++k) {
    CHECK(t.state[k] == kMdrNoTension);
    if (t.yielded[k]) CHECK(t.a[k] == Approx(0.5 * t.B[k]).epsilon(1e-12));
  }
  // unloading: a stays at its loaded value while the springs stretch within Delta l (state 2),
  // then peels; states never go back while unloading
  int prev = kMdrNoTension;
  int sep = -1;
  for (int k = n1; k < n2 && sep < 0; ++k) {
    CHECK(t.state[k] >= prev);
    if (t.state[k] == kMdrTensionWithin) CHECK(t.a[k] == Approx(t.a[n1 - 1]).epsilon(1e-12));
    prev = t.state[k];
    if (prev == kMdrSeparated) sep = k;
  }
  REQUIRE(sep > 0);
  // separated: no force while moving apart
  for (int k = sep; k < n2; ++k) CHECK(t.F[k] == 0.0);
  // apart: zero; pressed again: compressive contact re-forms (state 1) and adhesion with it
  bool reformed = false, tension_again = false;
  for (int k = n2; k < t.size(); ++k) {
    if (path[k] > t.delta_p[n2 - 1] && t.state[k] == kMdrNoTension && t.F[k] > 0) reformed = true;
    if (reformed && t.F[k] < 0) tension_again = true;
  }
  CHECK(reformed);
  CHECK(tension_again);
  // same pull-off the second time (the indenter shape is that of delta_max)
  double m1 = 0, m2 = 0;
  for (int k = 0; k < n2; ++k) m1 = std::max(m1, -t.F[k]);
  for (int k = n2; k < t.size(); ++k) m2 = std::max(m2, -t.F[k]);
  CHECK(m2 == Approx(m1).epsilon(1e-3));
}

TEMPLATE_LIST_TEST_CASE("MDR adhesion: halving the increment changes forces and pull-off by < 0.5%",
                        "[mdr][adhesion][convergence]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double E = 1.0, R = 1.0, Eeff = E / (1 - kNu * kNu);
  const double gamma = Eeff * R / 2.2e4;
  for (double EY : {0.0, 12.5, 200.0}) {
    for (double dmax : {4e-3, 0.2, 0.4}) {
      if ((EY == 0.0) != (dmax < 0.01)) continue;  // elastic case alone; plastic cases of Fig. 13
      const double Y = EY == 0.0 ? kInf : E / EY;
      const auto c = side_constants<T>(E, kNu, Y);
      // The unloading increment is a fraction of the elastic recovery delta_max - delta_p (after
      // plastic loading it is a few percent of delta_max: a step of delta_max/300 would put only a
      // handful of samples on the whole unloading curve).
      std::vector<double> pre;
      append_ramp(pre, 0.0, dmax, 300);
      const double dp = run_side_path<D, T, true, true>(c, gamma, 1, R, pre).delta_p.back();
      const double span = dmax - dp;
      auto path = [&](int n) {
        std::vector<double> p;
        append_ramp(p, 0.0, dmax, n);
        append_ramp(p, dmax, dp - 1.5 * span, 2 * n);
        return p;
      };
      const int n = 300;
      const SideTrace coarse = run_side_path<D, T, true, true>(c, gamma, 1, R, path(n));
      const SideTrace fine = run_side_path<D, T, true, true>(c, gamma, 1, R, path(2 * n));
      INFO("E/Y = " << EY << ", delta_max/R = " << dmax << ", recovery/R = " << span);
      REQUIRE(separation_step(coarse) > 0);
      REQUIRE(separation_step(fine) > 0);
      double Fscale = 0;
      for (double f : fine.F) Fscale = std::max(Fscale, std::fabs(f));
      double worst = 0.0;
      for (int k = 0; k < coarse.size(); ++k) {
        // the coarse run's step k is the fine run's step 2k+1; skip the steps at which either
        // run separates (a discrete event between two samples)
        if (coarse.state[k] == kMdrSeparated || fine.state[2 * k + 1] == kMdrSeparated) continue;
        worst = std::max(worst, std::fabs(coarse.F[k] - fine.F[2 * k + 1]));
      }
      CHECK(worst / Fscale < 5e-3);
      const double pc = max_tension(coarse), pf = max_tension(fine);
      CHECK(pc > 0.0);
      CHECK(std::fabs(pc - pf) / pf < 5e-3);
    }
  }
}

TEMPLATE_LIST_TEST_CASE("MDR adhesion guards: critical radius and peeling root at their edges",
                        "[mdr][adhesion][guard]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  Kokkos::View<double**, Kokkos::LayoutRight, D> o("o", 8, 4);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        const T E = 1, B = 2;
        // lambda = E A^2 / (xi^2 pi gamma B) from 1e-6 to 1e12 (tiny to huge adhesion)
        const T gammas[4] = {T(1e3), T(1), T(1e-4), T(1e-10)};
        for (int k = 0; k < 4; ++k) {
          for (int xi = 1; xi <= 3; xi += 2) {
            const T A = T(0.1);
            const T ac = mdr_critical_radius(E, gammas[k], T(xi), A, B);
            const int row = 2 * k + (xi == 3);
            o(row, 0) = ac;
            // (15): d g_1D/da = xi sqrt(pi gamma / (2 E a)) at a_c
            o(row, 1) = mdr_ellipse_gap_slope(A, B, ac);
            o(row, 2) = T(xi) * math::sqrt(constants<T>::pi * gammas[k] / (T(2) * E * ac));
            // peeling root at the edge: d = g(a_c) - Delta l(a_c) (the minimum for xi = 1) gives a_c
            const T d = mdr_ellipse_gap(A, B, ac) - mdr_critical_extension(E, gammas[k], ac);
            const T a_hi = T(0.5) * B;
            o(row, 3) = (ac < a_hi) ? mdr_peeling_radius(E, gammas[k], A, B, d, ac, a_hi) : ac;
          }
        }
      });
  auto h = to_host(o);
  const double tol = sizeof(T) >= 8 ? 1e-8 : 2e-3;
  for (int r = 0; r < 8; ++r) {
    INFO("row " << r);
    CHECK(h(r, 0) > 0.0);
    CHECK(h(r, 0) <= 1.0);
    if (h(r, 0) < 0.999) CHECK(h(r, 1) == Approx(h(r, 2)).epsilon(tol));
    CHECK(h(r, 3) == Approx(h(r, 0)).epsilon(std::sqrt(tol)));
  }
  // force control separates at a larger radius than displacement control
  for (int k = 0; k < 4; ++k) CHECK(h(2 * k + 1, 0) >= h(2 * k, 0));
}
