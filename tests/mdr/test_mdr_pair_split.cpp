// MDR particle pairs of unequal spheres: the limits any pair construction must meet, for the
// default split (MdrPairSplit::equal_pair, detail/mdr_pair_equal.hpp):
//   (a) elastic pairs are Hertz with E* and R* at any radius and modulus ratio;
//   (b) same-material plastic pairs are the equal pair with the same R* (radius 2 R*) at the same
//       delta: loading, unloading, reloading and adhesion (the similarity of same-material
//       spheres: one material, one contact pressure, so both bodies yield together);
//   adhesive elastic pairs pull off at JKR's 3/2 pi Delta gamma R*; radius growth gives each
//   particle of a same-material pair its share of the displaced volume.
// Passivity (c) is the fuzz's (tests/stability) and test_mdr_pair_stability's; the geometric
// option (d) has its own cases in test_mdr_pair_stability.cpp. The measured comparison of the
// splits is docs/mdr-pair-split-evaluation.md.
#include "contact_stepper.hpp"
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace epac;
using namespace epac::test;

namespace {

double plane_strain(double E, double nu) { return E / (1 - nu * nu); }

// A closed path in units of R*: load to 0.1, unload to 0.05, reload to 0.15, unload to a gap.
std::vector<double> load_unload_path(double Rs, int per_segment) {
  std::vector<double> x{0.0};
  append_ramp(x, 0.0, 0.1, per_segment);
  append_ramp(x, 0.1, 0.05, per_segment / 2);
  append_ramp(x, 0.05, 0.15, per_segment);
  append_ramp(x, 0.15, -0.05, 2 * per_segment);
  for (double& v : x) v *= Rs;
  return x;
}

template <class Model>
std::vector<double> forces_along(const Model& model, double R0, double R1, int m0, int m1,
                                 const std::vector<double>& path) {
  ContactStepper<Model> s(model, R0, R1, m0, m1);
  std::vector<double> F;
  F.reserve(path.size());
  for (double d : path) F.push_back(s.step(d));
  return F;
}
}  // namespace

// (a) MDR's side law is the ellipse law (30)-(31), Hertz to first order (1 - 0.075 d/R'), so at
// delta/R* <= 0.01 the side with the largest d_s/R'_s = w_s^2 delta/R* (the soft side of a modulus
// ratio of 100: w ~ 1) is 7.5e-4 off; the bound 1e-3 is the 0.1%. The old default split
// (MdrPairSplit::balanced) misses it by a factor of up to 52 with unequal moduli.
TEMPLATE_LIST_TEST_CASE("MDR pair split: elastic unequal pairs are Hertz with E* and R*", "[mdr][pair][split]",
                        BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity>, D>;
  const double E = 1e8, R0 = 1e-3;
  const double tol = 1e-3;
  for (double mod : {0.01, 0.1, 1.0 / 3, 1.0, 3.0, 10.0, 100.0})  // E_1/E_0, both ways
    for (double ratio : {1.0, 2.0, 5.0, 10.0, 30.0, 100.0}) {
      const double nu1 = mod == 1.0 ? 0.3 : 0.2;  // one material when mod = 1
      const M model = M::create({mdr_material(E, 0.3, kInf), mdr_material(E * mod, nu1, kInf)});
      const int m1 = mod == 1.0 ? 0 : 1;
      const double R1 = ratio * R0, Rs = R0 * R1 / (R0 + R1);
      const double Es = 1.0 / (1.0 / plane_strain(E, 0.3) + 1.0 / plane_strain(E * mod, nu1));
      ContactStepper<M> s(model, R0, R1, 0, m1);
      double worst = 0;
      for (int k = 1; k <= 40; ++k) {
        const double d = 0.01 * Rs * k / 40;
        const double F = s.step(d);
        const double F_hertz = 4.0 / 3.0 * Es * std::sqrt(Rs) * std::pow(d, 1.5);
        worst = std::max(worst, std::fabs(F / F_hertz - 1));
      }
      INFO("E_1/E_0 " << mod << ", R_1/R_0 " << ratio << ": worst |F/F_Hertz - 1| " << worst);
      CHECK(worst <= tol);
    }
}

// (b) Both sides of a same-material pair are the side of the equal pair (radius 2 R*, depth
// delta/2), with the same constants and history: the forces agree to round-off of R* E_s/E*
// against 2 R* (1e-12 measured in double). The old default was up to 51% off, the authors'
// radical plane 39% (docs/models.md's table).
TEMPLATE_LIST_TEST_CASE("MDR pair split: same-material plastic pairs are the equal pair with the same R*",
                        "[mdr][pair][split]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kAdhesion>, D>;
  const double E = 1e8, R0 = 1e-3;
  const double tol = std::is_same<T, float>::value ? 2e-4 : 1e-9;
  for (double gamma : {0.0, 0.5})
    for (double EY : {20.0, 200.0, 1000.0})
      for (double ratio : {1.5, 3.0, 10.0}) {
        const M model = M::create({mdr_material(E, 0.3, E / EY, gamma)});
        const double R1 = ratio * R0, Rs = R0 * R1 / (R0 + R1);
        const std::vector<double> path = load_unload_path(Rs, 200);
        const std::vector<double> F = forces_along(model, R0, R1, 0, 0, path);
        const std::vector<double> F_equal = forces_along(model, 2 * Rs, 2 * Rs, 0, 0, path);
        double peak = 0, worst = 0, tension = 0;
        for (double f : F_equal) peak = std::max(peak, std::fabs(f));
        for (std::size_t k = 0; k < F.size(); ++k) {
          worst = std::max(worst, std::fabs(F[k] - F_equal[k]) / peak);
          tension = std::min(tension, F_equal[k]);
        }
        INFO("gamma " << gamma << ", E/Y " << EY << ", R_1/R_0 " << ratio << ": worst |F - F_equal| / peak " << worst);
        CHECK(worst <= tol);
        CHECK(peak > 0);
        if (gamma > 0) CHECK(tension < 0);  // the adhesive branch was walked
      }
}

// The table through the library: ratio 2 and 5, E/Y 200, delta/R* 0.03 / 0.06 / 0.1 all
// 1.000 for the default; the old default gave 0.88 / 0.86 / 0.84 and 0.65 / 0.62 / 0.58, so the
// same check on MdrPairSplit::balanced fails (kept here: this test can tell the splits apart).
TEMPLATE_LIST_TEST_CASE("MDR pair split: the issue's similarity table, default against the old balanced split",
                        "[mdr][pair][split]", Backends) {
  using D = TestType;
  using M = Mdr<double, Effects<kPlasticity>, D>;
  const double E = 1e8, R0 = 1e-3;
  MdrOptions old_default;
  old_default.pair_split = MdrPairSplit::balanced;
  const M model = M::create({mdr_material(E, 0.3, E / 200)});
  const M old_model = M::create({mdr_material(E, 0.3, E / 200)}, old_default);
  for (double ratio : {2.0, 5.0}) {
    const double R1 = ratio * R0, Rs = R0 * R1 / (R0 + R1);
    std::vector<double> path{0.0};
    append_ramp(path, 0.0, 0.1 * Rs, 500);
    const std::vector<double> F = forces_along(model, R0, R1, 0, 0, path);
    const std::vector<double> F_old = forces_along(old_model, R0, R1, 0, 0, path);
    const std::vector<double> F_equal = forces_along(model, 2 * Rs, 2 * Rs, 0, 0, path);
    for (int k : {150, 300, 500}) {
      INFO("R_1/R_0 " << ratio << ", delta/R* " << path[k] / Rs << ": default " << F[k] / F_equal[k] << ", balanced "
                      << F_old[k] / F_equal[k]);
      CHECK(F[k] / F_equal[k] == Approx(1.0).epsilon(1e-9));
      CHECK(F_old[k] / F_equal[k] < 0.9);  // 0.58-0.88 measured
    }
  }
}

// Adhesive elastic pairs (series share of Delta gamma): the largest tension of a quasi-static
// unload is JKR's 3/2 pi Delta gamma R* (measured 0.9992-0.9999; the old default gave 0.05-0.72
// of it with unequal radii or moduli). 1% allows the step of the unload (4000 steps).
TEMPLATE_LIST_TEST_CASE("MDR pair split: adhesive elastic unequal pairs pull off at JKR of R* and E*",
                        "[mdr][pair][split][adhesion]", Backends) {
  using D = TestType;
  using M = Mdr<double, Effects<kPlasticity | kAdhesion>, D>;
  const double E = 1e8, R0 = 1e-3, gamma = 0.5;
  const double cases[][2] = {{1, 1}, {5, 1}, {5, 3}, {20, 0.1}};  // R_1/R_0, E_1/E_0
  for (const auto& c : cases) {
    const M model = M::create({mdr_material(E, 0.3, kInf, gamma), mdr_material(E * c[1], 0.3, kInf, gamma)});
    const double R1 = c[0] * R0, Rs = R0 * R1 / (R0 + R1);
    const double Es = 1.0 / (1.0 / plane_strain(E, 0.3) + 1.0 / plane_strain(E * c[1], 0.3));
    const double a0 = std::cbrt(9 * M_PI * gamma * Rs * Rs / (2 * Es));  // JKR zero-load radius
    const double load = 3 * a0 * a0 / Rs;
    ContactStepper<M> s(model, R0, R1, 0, 1);
    for (int k = 1; k <= 400; ++k) s.step(load * k / 400);
    double tension = 0;
    for (int k = 1; k <= 4000; ++k) tension = std::min(tension, s.step(load * (1 - 1.5 * k / 4000.0)));
    const double jkr = 1.5 * M_PI * gamma * Rs;
    INFO("R_1/R_0 " << c[0] << ", E_1/E_0 " << c[1] << ": largest tension / JKR " << -tension / jkr);
    CHECK(-tension / jkr == Approx(1.0).epsilon(0.01));
  }
}

// Radius growth (MDR (37)) under the equal-pair sides: each side's cap is cut from its sphere
// R'_s (mdr_growth_add_side's R_cap), the particle's compliance share of the pair's lens, so each
// particle of a same-material pair gains about half the displaced volume: measured 0.49-0.52
// (small) and 0.38-0.44 (large) of the lens at ratios 2-5, the equal pair 0.47 each. The old
// default put it on the small particle (1.13-1.24 of the lens; the large one 0.0x).
TEMPLATE_LIST_TEST_CASE("MDR pair split: radius growth shares a same-material pair's displaced volume",
                        "[mdr][pair][split][growth]", Backends) {
  using D = TestType;
  using MG = Mdr<double, Effects<kPlasticity | kRadiusGrowth>, D>;
  const double E = 1e8, R0 = 1e-3;
  auto cap = [](double d, double R) { return M_PI * d * d * (3 * R - d) / 3; };
  const MG model = MG::create({mdr_material(E, 0.3, E / 200)});
  for (double ratio : {2.0, 5.0}) {
    const double R1 = ratio * R0, Rs = R0 * R1 / (R0 + R1), dmax = 0.3 * Rs;
    std::vector<double> path;
    append_ramp(path, 0.0, dmax, 2000);
    const PairTrace t = run_pair_path<MG, D>(model, R0, R1, 0, path);
    const PairTrace te = run_pair_path<MG, D>(model, 2 * Rs, 2 * Rs, 0, path);
    auto lens_of = [&](double a, double b) {
      const double h0 = double(mdr_side0_height(dmax, a, b));
      return cap(h0, a) + cap(dmax - h0, b);
    };
    const double lens = lens_of(R0, R1), lens_e = lens_of(2 * Rs, 2 * Rs);
    const double V0 = 4.0 / 3 * M_PI * (std::pow(t.R0.back(), 3) - R0 * R0 * R0) / lens;
    const double V1 = 4.0 / 3 * M_PI * (std::pow(t.R1.back(), 3) - R1 * R1 * R1) / lens;
    const double Ve = 4.0 / 3 * M_PI * (std::pow(te.R0.back(), 3) - 8 * Rs * Rs * Rs) / lens_e;
    INFO("R_1/R_0 " << ratio << ": volume gained / lens: small " << V0 << ", large " << V1 << ", equal pair " << Ve);
    REQUIRE(t.finite);
    CHECK(V0 > 0.3);
    CHECK(V0 < 0.65);
    CHECK(V1 > 0.3);
    CHECK(V1 < 0.65);
    CHECK(V0 + V1 == Approx(2 * Ve).epsilon(0.15));  // the equal pair's total, within 15%
  }
}

// The balance solve's warm start (mdr_model.hpp balance_guess) under radius growth: an unlike
// plastic pair (two materials: the solve runs every step) loaded monotonically, the centres
// closing by the path while the particles grow, so growth adds to the apparent overlap as in a
// packing. The first guess, the last step's root moved along its tangent, d_0 + w (delta_now -
// delta), is second order in the step's change of delta; growth (1.1% of R_o here, soft side)
// moves the root a little more. Why 1e-5 of delta: one Newton step from a relative error e lands
// within about e^2 <= 1e-10 (the balance tolerance, mdr_balance_tolerance), so a guess that close
// costs two pair evaluations per step, not three (measured with a counter in the solve: 2.03 per
// step at 2,000 steps, 97.8% of the guesses within 1e-5 and 99.5% within 1e-4; 2.001 at 20,000).
// The rest are the steps where the tangent turns fast (the sides' onsets of yield). A warm start
// not kept (the compliance split: ~1e-2 off) or kept without its slope (w delta/k off at step k)
// misses on most steps; a guess kept net of growth (root - growth_0, as if only side 0's growth
// moved the root) was measured worse, 2.53 evaluations per step, so the guess stays in delta.
TEMPLATE_LIST_TEST_CASE("MDR pair split: the balance warm start stays second order under radius growth",
                        "[mdr][pair][split][growth]", Backends) {
  using D = TestType;
  using MG = Mdr<double, Effects<kPlasticity | kRadiusGrowth>, D>;
  using PF = MdrPairFields<typename MG::effects>;
  const double E = 1e8, R0 = 1e-3, R1 = 3e-3, Rs = R0 * R1 / (R0 + R1);
  const MG model = MG::create({mdr_material(E, 0.3, E / 200), mdr_material(3 * E, 0.3, 3 * E / 100)});
  ContactStepper<MG, true> s(model, R0, R1, 0, 1);
  const int n = 2000;
  int warm = 0, within = 0, near = 0;
  for (int k = 1; k <= n; ++k) {
    // centre distance R0_o + R1_o - d: the apparent overlap adds both growths
    const double delta = 0.3 * Rs * k / n + (s.radius(0) - R0) + (s.radius(1) - R1);
    const std::vector<double> h = s.history();
    s.step(delta);
    if (h[PF::split_delta] == 0.0) continue;  // no last root yet (elastic, or first plastic step)
    const double guess = h[PF::split_d0] + h[PF::split_slope] * (delta - h[PF::split_delta]);
    const double root = s.history()[PF::split_d0];
    ++warm;
    if (std::fabs(root - guess) <= 1e-5 * delta) ++within;
    if (std::fabs(root - guess) <= 1e-3 * delta) ++near;
  }
  INFO("warm-started steps " << warm << ", guess within 1e-5 delta of the root " << within << ", within 1e-3 " << near
                             << "; R_0/R_0,o " << s.radius(0) / R0 << ", R_1/R_1,o " << s.radius(1) / R1);
  CHECK(s.radius(0) / R0 > 1.005);  // the growth this case is about took place
  CHECK(warm > n / 2);
  CHECK(within >= 0.95 * warm);
  CHECK(near >= 0.99 * warm);
}

// MdrPairSplit::geometric_authors: the authors' unloading path (LAMMPS gran_sub_mod_normal.cpp)
// below the largest overlap, the radical plane at and above it; the same line as geometric's for
// equal spheres with equal residuals; geometric's path where the residuals sum to dmax or more.
TEST_CASE("MDR pair split: geometric_authors follows the authors' unloading line", "[mdr][pair][split]") {
  const double R0 = 1e-3, R1 = 1.4e-3, dmax = 0.2e-3, dp0 = 0.09e-3, dp1 = 0.05e-3;
  const double h0 = mdr_side0_height(dmax, R0, R1);
  for (double delta : {0.25e-3, 0.2e-3}) {  // loading: the radical plane, as geometric
    const auto a = mdr_split_overlap(delta, std::max(delta, dmax), R0, R1, dp0, dp1, true);
    const auto g = mdr_split_overlap(delta, std::max(delta, dmax), R0, R1, dp0, dp1);
    CHECK(a.d0 == g.d0);
    CHECK(a.d1 == g.d1);
  }
  double worst = 0.0;
  for (double delta : {0.18e-3, 0.15e-3, 0.14e-3, 0.1e-3, 0.0}) {  // unloading, and past the residuals
    const auto a = mdr_split_overlap(delta, dmax, R0, R1, dp0, dp1, true);
    const auto g = mdr_split_overlap(delta, dmax, R0, R1, dp0, dp1);
    const double lammps = h0 + (dp0 - h0) * (delta - dmax) / ((dp0 + dp1) - dmax);
    CHECK(a.d0 == Approx(lammps).epsilon(1e-14));
    CHECK(a.d0 + a.d1 == Approx(delta).margin(1e-18));
    worst = std::max(worst, std::abs(a.d0 - g.d0));
  }
  INFO("largest |d_0(geometric_authors) - d_0(geometric)| " << worst);
  CHECK(worst > 1e-3 * dmax);  // unequal spheres: the two paths differ
  // equal spheres, equal residuals: one line
  for (double delta : {0.15e-3, 0.1e-3, 0.02e-3}) {
    const auto a = mdr_split_overlap(delta, dmax, R0, R0, 0.05e-3, 0.05e-3, true);
    const auto g = mdr_split_overlap(delta, dmax, R0, R0, 0.05e-3, 0.05e-3);
    CHECK(a.d0 == Approx(g.d0).epsilon(1e-12));
  }
  // residuals summing to dmax or more (the authors' denominator >= 0): geometric's path
  const auto a = mdr_split_overlap(0.15e-3, dmax, R0, R1, 0.1e-3, 0.1e-3, true);
  const auto g = mdr_split_overlap(0.15e-3, dmax, R0, R1, 0.1e-3, 0.1e-3);
  CHECK(a.d0 == g.d0);
  CHECK(std::isfinite(a.d0));
}
