// MDR robustness sweep: E/Y from 6.25 to 1e4, delta/R up to 0.6, Delta gamma from 0 to E* R/1e3,
// radii from 1e-7 to 1e-1 m: no NaN or Inf, in double and float. Plus the report numbers (hidden
// test "[.report]": peak force and residual displacement of the two-flat scene, pull-off forces).
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

using namespace epac;
using namespace epac::test;

namespace {
bool all_finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("MDR sweep: no NaN or Inf over E/Y, overlap, surface energy, radius", "[mdr][sweep]",
                        BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kAdhesion | kRadiusGrowth | kDamping | kFriction>, D>;
  int runs = 0;
  for (double R0 : {1e-7, 1.0, 1e-1}) {
    const double E = R0 == 1.0 ? 1.0 : 1e9;  // nondimensional, and SI with E = 1 GPa
    const double Eeff = E / (1 - kNu * kNu);
    for (double EY : {6.25, 25.0, 200.0, 1e3, 1e4}) {
      for (double g : {0.0, 1e-6, 1e-4, 1e-3}) {
        const double gamma = g * Eeff * R0;
        // single side, fine steps, load-unload-reload-unload past separation
        for (double dmax : {0.05, 0.3, 0.6}) {
          std::vector<double> path;
          append_ramp(path, 0.0, dmax * R0, 200);
          append_ramp(path, dmax * R0, -0.05 * R0, 400);
          append_ramp(path, -0.05 * R0, dmax * R0, 200);
          append_ramp(path, dmax * R0, -0.1 * R0, 400);
          for (int xi : {1, 3}) {
            const auto c = side_constants<T>(E, kNu, E / EY);
            const SideTrace t = run_side_path<D, T, true, true>(c, gamma, xi, R0, path);
            INFO("R0 = " << R0 << ", E/Y = " << EY << ", gamma/(E* R) = " << g << ", delta_max/R = " << dmax
                         << ", xi = " << xi);
            CHECK(all_finite(t.F));
            CHECK(all_finite(t.area));
            CHECK(all_finite(t.a));
            CHECK(all_finite(t.d1De));
            CHECK(all_finite(t.delta_p));
            ++runs;
          }
        }
        // the full model on the two-flat scene with growth, damping, friction (a subset: each
        // step launches several small kernels)
        if ((EY == 6.25 || EY == 1e4) && (g == 0.0 || g == 1e-3)) {
          const M model = M::create({mdr_material(E, kNu, E / EY, gamma, 0.5), rigid_wall_material()});
          std::vector<double> path;
          append_ramp(path, 0.0, 0.6 * R0, 60);
          append_ramp(path, 0.6 * R0, 0.55 * R0, 60);
          append_ramp(path, 0.55 * R0, -0.05 * R0, 20);
          const FlatTrace t = run_flats<M, D>(model, R0, path, false);
          INFO("flats: R0 = " << R0 << ", E/Y = " << EY << ", gamma/(E* R) = " << g);
          CHECK(all_finite(t.F_primary));
          CHECK(all_finite(t.area));
          CHECK(all_finite(t.pressure));
          CHECK(all_finite(t.R));
          CHECK(all_finite(t.V));
          for (double v : t.V) CHECK(v > 0.0);
        }
      }
    }
  }
  CHECK(runs == 3 * 5 * 4 * 3 * 2);
}

// Report numbers (run with: test_mdr "[.report]"). Two flats, each displaced by delta_o, load to
// delta_o/R_o = 0.5 and back; E = 1, R_o = 1, nu = 0.3; radius growth with the default rule.
TEST_CASE("MDR report: two-flat peak forces, residual displacements, pull-off forces", "[.report]") {
  using D = DeviceOf<Kokkos::DefaultHostExecutionSpace>;  // host: many small launches
  using T = double;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  const double E = 1.0, R0 = 1.0;
  std::printf("two flats, delta_o per flat; F/(E R_o^2) at delta_o/R_o = 0.5; residual delta_o/R_o\n");
  std::printf("%8s %12s %12s %10s %10s %12s %12s\n", "E/Y", "F_peak", "residual", "R/R_o", "V/V_o", "A/(pi R_o^2)",
              "p/Y");
  for (double EY : {6.25, 12.5, 25.0, 50.0, 100.0, 200.0}) {
    const M model = M::create({mdr_material(E, kNu, E / EY), rigid_wall_material()});
    std::vector<double> path;
    append_ramp(path, 0.0, 0.5, 5000);
    append_ramp(path, 0.5, 0.2, 30000);  // 1e-5 R_o steps: resolves the (small) elastic recovery
    const FlatTrace t = run_flats<M, D>(model, R0, path, false);
    const int peak = 4999;
    double residual = -1;
    for (size_t k = 5000; k < t.F_primary.size(); ++k)
      if (t.F_primary[k] <= 0.0) {
        residual = t.delta_o[k];
        break;
      }
    std::printf("%8.2f %12.5e %12.5f %10.5f %10.6f %12.5f %12.5f\n", EY, t.F_primary[peak], residual, t.R[peak],
                t.V[peak] / (4.0 / 3.0 * M_PI), t.area[peak] / M_PI, t.pressure[peak] * EY);
  }
  std::printf("\npull-off (largest tension) / (pi gamma R), single side, E* R/gamma = 2.2e4\n");
  const double Eeff = E / (1 - kNu * kNu);
  const double gamma = Eeff * R0 / 2.2e4;
  for (int xi : {1, 3}) {
    for (double EY : {0.0, 12.5, 200.0}) {
      for (double dmax : {4e-3, 0.1, 0.4}) {
        if ((EY == 0.0) != (dmax < 0.01)) continue;
        const double Y = EY == 0.0 ? std::numeric_limits<double>::infinity() : E / EY;
        const auto c = side_constants<T>(E, kNu, Y);
        std::vector<double> pre;
        append_ramp(pre, 0.0, dmax, 2000);
        const SideTrace tp = run_side_path<D, T, true, true>(c, gamma, xi, R0, pre);
        const double dp = tp.delta_p.back();
        const double span = dmax - dp;
        double last = 0;
        for (int n : {20000, 40000}) {
          std::vector<double> path = pre;
          append_ramp(path, dmax, dp - 1.5 * span, n);
          const SideTrace t = run_side_path<D, T, true, true>(c, gamma, xi, R0, path);
          double m = 0;
          for (double f : t.F) m = std::max(m, -f);
          std::printf("xi=%d E/Y=%-6g delta_max/R=%-6g yielded=%d steps=%6d  F_pull/(pi gamma R) = %.5f%s\n", xi, EY,
                      dmax, tp.yielded.back(), n, m / (M_PI * gamma * R0),
                      last > 0 ? (std::fabs(m - last) / m < 1e-3 ? "  (converged to 1e-3)" : "  (NOT converged)") : "");
          last = m;
        }
      }
    }
  }
}
