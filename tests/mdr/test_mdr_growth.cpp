// MDR apparent-radius growth (37)-(39): one sphere between moving flats, die compaction, the
// update-kernel guards, increment convergence of the whole load-unload curve.
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace epac;
using namespace epac::test;

namespace {
std::vector<double> two_flat_path(double peak, int n_load, int n_unload, double end = 0.0) {
  std::vector<double> p;
  append_ramp(p, 0.0, peak, n_load);
  append_ramp(p, peak, end, n_unload);
  return p;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("MDR growth: R non-decreasing, V positive, growth only after yield (two flats)",
                        "[mdr][growth]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  const double E = 1.0, R0 = 1.0;
  for (auto rule : {MdrGrowthRule::plastic_loading, MdrGrowthRule::yielded_contacts}) {
    for (double EY : {12.5, 50.0}) {
      MdrOptions opt;
      opt.growth_rule = rule;
      const M model = M::create({mdr_material(E, kNu, E / EY), rigid_wall_material()}, opt);
      std::array<int, kMdrGuardCount> guards{};
      const FlatTrace t = run_flats<M, D>(model, R0, two_flat_path(0.5, 500, 500), false, &guards);
      INFO("E/Y = " << EY << ", rule = " << int(rule));
      const double V0 = 4.0 / 3.0 * M_PI;
      for (size_t k = 0; k < t.R.size(); ++k) {
        if (k > 0) CHECK(t.R[k] >= t.R[k - 1]);
        CHECK(t.V[k] > 0.0);
        CHECK(t.V[k] <= V0 * (1 + 1e-6));  // compressed: the elastic volume change is negative
        if (rule == MdrGrowthRule::plastic_loading && !t.yielded[k]) CHECK(t.R[k] == R0);
      }
      // grows in the plastic range (Fig. 11: the apparent radius follows plastic incompressibility)
      CHECK(t.R[499] > 1.02 * R0);
      // no growth while unloading
      CHECK(t.R.back() == t.R[500]);
      CHECK(guards[kMdrGuardDenominator] == 0);
      CHECK(guards[kMdrGuardRadiusCap] == 0);
      CHECK(guards[kMdrGuardVolume] == 0);
    }
  }
}

TEMPLATE_LIST_TEST_CASE("MDR growth: die compaction, lateral flats loaded only through radius growth (E/Y = 20)",
                        "[mdr][growth][die]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double E = 1.0, R0 = 1.0, Y = E / 20.0;
  const auto path = two_flat_path(0.3, 600, 600);
  {
    using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth | kDamping>, D>;
    const M model = M::create({mdr_material(E, kNu, Y), rigid_wall_material()});
    const FlatTrace t = run_flats<M, D>(model, R0, path, true);
    bool seen = false;
    for (size_t k = 0; k < t.R.size(); ++k) {
      // the secondary force of step k is evaluated with the radius before that step's update
      const double R_seen = k == 0 ? R0 : t.R[k - 1];
      if (R_seen == R0) CHECK(t.F_secondary[k] == 0.0);
      if (t.F_secondary[k] > 0.0) {
        CHECK(R_seen > R0);
        seen = true;
      }
    }
    CHECK(seen);
    // the secondary contacts keep a force after unloading: radial expansion is permanent (Fig. 12(b))
    CHECK(t.F_secondary.back() > 0.0);
    CHECK(t.F_primary[599] > 0.0);
  }
  {
    // without radius growth the lateral flats never see a force
    using M = Mdr<T, Effects<kPlasticity | kDamping>, D>;
    const M model = M::create({mdr_material(E, kNu, Y), rigid_wall_material()});
    const FlatTrace t = run_flats<M, D>(model, R0, path, true);
    for (double f : t.F_secondary) CHECK(f == 0.0);
  }
}

TEMPLATE_LIST_TEST_CASE("MDR growth: halving the increment changes the load-unload curve by < 0.5%",
                        "[mdr][growth][convergence]", Backends) {
  using D = TestType;
  using T = double;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  const double E = 1.0, R0 = 1.0;
  for (double EY : {6.25, 50.0}) {
    const M model = M::create({mdr_material(E, kNu, E / EY), rigid_wall_material()});
    // The unloading (0.5 -> 0.45 R_o) passes the residual: the whole stiff unloading branch is
    // compared (its slope is ~ F_peak / 0.01 R_o, so any lag of R is amplified there; see the
    // delta_max convention (19) in mdr_side_force.hpp). Same step on loading and unloading.
    const int n = 1000;
    const FlatTrace a = run_flats<M, D>(model, R0, two_flat_path(0.5, n, n / 10, 0.45), false);
    const FlatTrace b = run_flats<M, D>(model, R0, two_flat_path(0.5, 2 * n, n / 5, 0.45), false);
    double peak = 0, worst = 0;
    for (double f : b.F_primary) peak = std::max(peak, f);
    for (size_t k = 0; k < a.F_primary.size(); ++k)
      worst = std::max(worst, std::fabs(a.F_primary[k] - b.F_primary[2 * k + 1]));
    INFO("E/Y = " << EY);
    CHECK(worst / peak < 5e-3);
    CHECK(std::fabs(a.R[n - 1] - b.R[2 * n - 1]) / (b.R[2 * n - 1] - R0) < 5e-2);
  }
}

TEMPLATE_LIST_TEST_CASE("MDR growth guards: denominator floor, radius cap, volume floor are applied and counted",
                        "[mdr][growth][guard]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  MdrGrowthState<T, D> gs;
  Kokkos::View<T*, D> r0("r0", 4), r("r", 4);
  Kokkos::deep_copy(r0, T(1));
  Kokkos::deep_copy(r, T(1));
  gs.attach(r0, r);
  gs.radius_cap = T(1.5);
  gs.denominator_floor = T(0.05);
  gs.volume_floor = T(0.1);
  const T fourpi = T(4) * constants<T>::pi;
  auto num = Kokkos::create_mirror_view(gs.numerator);
  auto den = Kokkos::create_mirror_view(gs.denominator);
  auto eps = Kokkos::create_mirror_view(gs.eps_sum);
  // 0: normal (D = -2 pi); 1: D -> 0 (den = 4 pi R^2); 2: huge growth (capped); 3: eps_sum = -5
  num(0) = T(1e-3);
  den(0) = T(0.5) * fourpi;
  eps(0) = T(-1e-3);
  num(1) = T(1e-3);
  den(1) = fourpi;
  eps(1) = T(0);
  num(2) = T(1e3);
  den(2) = T(0);
  eps(2) = T(0);
  num(3) = T(0);
  den(3) = T(0);
  eps(3) = T(-5);
  Kokkos::deep_copy(gs.numerator, num);
  Kokkos::deep_copy(gs.denominator, den);
  Kokkos::deep_copy(gs.eps_sum, eps);
  mdr_update_radii(gs);
  auto R = to_host(gs.radius);
  auto V = to_host(gs.volume);
  auto hits = to_host(gs.guard_hits);
  const double V0 = 4.0 / 3.0 * M_PI;
  const double tol = sizeof(T) >= 8 ? 1e-12 : 1e-5;
  // (37): dR = max(num / (den - 4 pi R^2), 0); num > 0 with D < 0 gives no growth
  CHECK(R(0) == Approx(1.0).epsilon(tol));
  CHECK(V(0) == Approx(V0 * (1 - 1e-3)).epsilon(tol));
  CHECK(R(1) == Approx(1.0).epsilon(tol));  // D floored at -0.05 * 4 pi: still finite, no NaN
  CHECK(R(2) == Approx(1.0).epsilon(tol));
  CHECK(hits(kMdrGuardDenominator) == 1);
  CHECK(hits(kMdrGuardVolume) == 1);
  CHECK(V(3) == Approx(0.1 * V0).epsilon(tol));
  // sums are reset
  auto n2 = to_host(gs.numerator);
  for (int p = 0; p < 4; ++p) CHECK(n2(p) == 0.0);
  // a compressive numerator with D < 0 grows R: dR = -num / |D|; a huge one hits the cap
  num(0) = T(-0.1);
  den(0) = T(0);  // dR = 0.1 / (4 pi) = 0.00796
  num(1) = T(-0.1);
  den(1) = fourpi;  // floored D = -0.05 * 4 pi: dR = 0.159
  num(2) = T(-1e3);
  den(2) = T(0);  // capped at 1.5
  num(3) = T(0);
  den(3) = T(0);
  Kokkos::deep_copy(gs.numerator, num);
  Kokkos::deep_copy(gs.denominator, den);
  Kokkos::deep_copy(gs.eps_sum, T(0));
  mdr_update_radii(gs);
  R = to_host(gs.radius);
  hits = to_host(gs.guard_hits);
  CHECK(R(0) == Approx(1.0 + 0.1 / (4 * M_PI)).epsilon(tol));
  CHECK(R(1) == Approx(1.0 + 0.1 / (0.05 * 4 * M_PI)).epsilon(tol));
  CHECK(R(2) == Approx(1.5).epsilon(tol));
  CHECK(hits(kMdrGuardDenominator) == 2);
  CHECK(hits(kMdrGuardRadiusCap) == 1);
  CHECK(V(3) > 0.0);
}

TEMPLATE_LIST_TEST_CASE("MDR growth: high confinement (six flats closing in) stays finite and bounded",
                        "[mdr][growth][guard]", Backends) {
  using D = TestType;
  using T = double;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  // die compaction pushed far: the primary flats to 0.7 R_o each while the lateral ones hold
  const M model = M::create({mdr_material(1.0, kNu, 1.0 / 20.0), rigid_wall_material()});
  std::array<int, kMdrGuardCount> guards{};
  const FlatTrace t = run_flats<M, D>(model, 1.0, two_flat_path(0.7, 700, 10, 0.69), true, &guards);
  for (size_t k = 0; k < t.R.size(); ++k) {
    CHECK(std::isfinite(t.F_primary[k]));
    CHECK(std::isfinite(t.F_secondary[k]));
    CHECK(t.R[k] <= 1.5 + 1e-12);
    CHECK(t.V[k] > 0.0);
  }
  INFO("guard hits: denominator " << guards[0] << ", cap " << guards[1] << ", volume " << guards[2]);
  CHECK(guards[kMdrGuardDenominator] + guards[kMdrGuardRadiusCap] > 0);  // the guards did act
}

TEMPLATE_TEST_CASE(
    "MdrDeltaMax: growth at a fixed apparent overlap is plastic loading for running_max (the "
    "authors' code), not for MDR (19)",
    "[mdr][growth]", double, float) {
  using T = TestType;
  const Material m = mdr_material(1e9, 0.3, 5e6);
  // the model passes a side the shift of delta_max: R - R_o by (19), 0 for the running maximum
  MdrOptions running;
  running.delta_max = MdrDeltaMax::running_max;
  CHECK(Mdr<T, Effects<kPlasticity | kRadiusGrowth>>::create({m}).growth_in_max == T(1));
  CHECK(Mdr<T, Effects<kPlasticity | kRadiusGrowth>>::create({m}, running).growth_in_max == T(0));
  const MdrSideConstants<T> c = mdr_side_constants<T>(m, MdrYieldOnset::elastic_law);
  const T R0 = T(1e-3), d = T(0.05e-3);  // delta/R = 0.05: yielded at E/Y = 200
  for (const bool paper : {true, false}) {
    MdrSideState<T> st;
    // load to d without growth: both conventions identical
    for (int k = 1; k <= 50; ++k) mdr_side_force<true, false>(c, T(0), T(1), d * T(k) / T(50), R0, T(0), st);
    REQUIRE(st.yielded != T(0));
    // the radius grows by 1 um while the apparent overlap stays d (a neighbour's growth pushed it)
    const T g = T(1e-6);
    const MdrSideResult<T> r = mdr_side_force<true, false>(c, T(0), T(1), d, R0 + g, paper ? g : T(0), st);
    if (paper) {
      CHECK_FALSE(r.loading);                       // delta_o = d - g is below delta_o,max = d
      CHECK(r.delta_max == Approx(double(d + g)));  // (19): delta_max moved with R
    } else {
      CHECK(r.loading);  // delta = d is at its running maximum
      CHECK(r.delta_max == Approx(double(d)));
    }
  }
}
