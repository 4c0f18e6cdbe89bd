// MDR one-side law: elastic limit, yield switch, hardening curve, unloading/reloading, residual
// displacement, and the guards of the ellipse and plastic-shape formulas.
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace epac;
using namespace epac::test;

namespace {
double eeff(double E) { return E / (1.0 - kNu * kNu); }
double hertz(double E_eff, double R, double d) { return 4.0 / 3.0 * E_eff * std::sqrt(R) * std::pow(d, 1.5); }
double hardening(double Y, double x) { return Y * (1.75 * std::exp(-4.4 * x) + 1.0); }
template <class T>
double rel_tol_of() {
  return sizeof(T) >= 8 ? 1e-12 : 2e-5;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("MDR side: small overlaps follow Hertz (25)", "[mdr][side]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double E = 1.0, R = 1.0;
  const auto c = side_constants<T>(E, kNu, std::numeric_limits<double>::infinity());
  std::vector<double> path;
  for (double x : {1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 3e-3, 1e-2, 5e-2}) path.push_back(x * R);
  const SideTrace t = run_side_path<D, T, true, false>(c, 0.0, 1.0, R, path);
  for (int k = 0; k < t.size(); ++k) {
    const double ratio = t.F[k] / hertz(eeff(E), R, path[k]);
    INFO("delta/R = " << path[k] << ", F/F_Hertz = " << ratio);
    if (path[k] <= 1e-2 * R) CHECK(std::fabs(ratio - 1.0) < 1e-3);
    // the ellipse A = 4R, B = 2R departs from Hertz at second order: F/F_H = 1 - 0.075 delta/R
    // + O((delta/R)^2) (the next term is 3.4e-3 (delta/R)^2)
    CHECK(std::fabs(ratio - (1.0 - 0.075 * path[k] / R)) < 4e-3 * (path[k] / R) * (path[k] / R) + 50 * rel_tol_of<T>());
    CHECK(t.yielded[k] == 0);
  }
}

TEMPLATE_LIST_TEST_CASE("MDR side: force and mean pressure are continuous at delta_Y, then follow the hardening curve",
                        "[mdr][side][yield]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double E = 1.0, R = 1.0;
  // float: the last step is 1e-9 of delta_Y in double; in float the step is ~100 ulp, and the
  // jump tolerance is the float rounding of the force formulas (~1e-5), not 1e-6.
  const double eta = sizeof(T) >= 8 ? 1e-9 : 1e-5;
  const double tol = sizeof(T) >= 8 ? 1e-6 : 1e-4;
  for (double EY : {6.25, 12.5, 25.0, 50.0, 200.0}) {
    const double Y = E / EY;
    const auto c = side_constants<T>(E, kNu, Y);
    const double dY = double(c.x_yield) * R;
    std::vector<double> below, above;
    append_ramp(below, 0.0, dY * (1 - eta), 50);
    append_ramp(above, 0.0, dY * (1 + eta), 50);
    const SideTrace tb = run_side_path<D, T, true, false>(c, 0.0, 1.0, R, below);
    const SideTrace ta = run_side_path<D, T, true, false>(c, 0.0, 1.0, R, above);
    INFO("E/Y = " << EY << ", delta_Y/R = " << dY);
    REQUIRE(tb.yielded.back() == 0);
    REQUIRE(ta.yielded.back() == 1);
    const double Fb = tb.F.back(), Fa = ta.F.back();
    CHECK(std::fabs(Fa - Fb) / Fb < tol);
    const double pb = Fb / tb.area.back(), pa = Fa / ta.area.back();
    CHECK(std::fabs(pa - pb) / pb < tol);
    CHECK(std::fabs(ta.area.back() - tb.area.back()) / tb.area.back() < tol);
    // at delta_Y the elastic law's mean pressure equals p_Y (the yield equation)
    CHECK(std::fabs(pb - hardening(Y, dY / R)) / pb < tol);
    // after yield, on loading, F / A_C = p_Y(delta_max/R): the hardening curve (16)+(21)
    std::vector<double> load;
    append_ramp(load, 0.0, 0.6 * R, 600);
    const SideTrace tl = run_side_path<D, T, true, false>(c, 0.0, 1.0, R, load);
    for (int k = 0; k < tl.size(); ++k) {
      if (!tl.yielded[k]) continue;
      const double p = tl.F[k] / tl.area[k];
      CHECK(std::fabs(p - hardening(Y, load[k] / R)) / p < 200 * rel_tol_of<T>());
    }
  }
}

TEMPLATE_LIST_TEST_CASE("MDR side: the paper's literal onset (40)-(41) jumps by the ellipse-vs-Hertz difference",
                        "[mdr][side][yield]", Backends) {
  using D = TestType;
  using T = double;
  const double E = 1.0, R = 1.0;
  for (double EY : {12.5, 200.0}) {
    const double Y = E / EY;
    const auto c = side_constants<T>(E, kNu, Y, MdrYieldOnset::hertz_40);
    const double dY = c.x_yield * R;
    // (41): the Hertz mean pressure (40) equals p_Y at delta_Y
    CHECK(4.0 * eeff(E) / (3.0 * M_PI * std::sqrt(R)) * std::sqrt(dY) == Approx(hardening(Y, dY / R)).epsilon(1e-12));
    std::vector<double> below, above;
    append_ramp(below, 0.0, dY * (1 - 1e-9), 20);
    append_ramp(above, 0.0, dY * (1 + 1e-9), 20);
    const SideTrace tb = run_side_path<D, T, true, false>(c, 0.0, 1.0, R, below);
    const SideTrace ta = run_side_path<D, T, true, false>(c, 0.0, 1.0, R, above);
    REQUIRE(ta.yielded.back() == 1);
    // plastic side starts at the Hertz force pi delta_Y R p_Y; elastic side is the ellipse force
    CHECK(ta.F.back() == Approx(hertz(eeff(E), R, dY)).epsilon(1e-6));
    CHECK(tb.F.back() == Approx(mdr_ellipse_force(eeff(E), 4 * R, 2 * R, dY)).epsilon(1e-6));
    const double jump = (ta.F.back() - tb.F.back()) / tb.F.back();
    CHECK(jump == Approx(0.075 * dY / R).epsilon(0.05));
    CHECK(ta.area.back() == Approx(tb.area.back()).epsilon(1e-6));  // (43): area continuous
  }
}

TEMPLATE_LIST_TEST_CASE("MDR side: unloading and reloading below delta_max retrace; residual grows with delta_max",
                        "[mdr][side][unload]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double E = 1.0, R = 1.0, Y = E / 25.0;
  const auto c = side_constants<T>(E, kNu, Y);
  double last_residual = 0.0;
  for (double dmax : {0.1, 0.2, 0.35, 0.5, 0.6}) {
    std::vector<double> path;
    const int n = 400;
    append_ramp(path, 0.0, dmax, n);           // load
    append_ramp(path, dmax, 0.0, n);           // unload to zero overlap
    append_ramp(path, 0.0, dmax, n);           // reload
    append_ramp(path, dmax, dmax * 1.05, 20);  // past delta_max: plastic loading again
    const SideTrace t = run_side_path<D, T, true, false>(c, 0.0, 1.0, R, path);
    const double Fpeak = t.F[n - 1];
    INFO("delta_max/R = " << dmax);
    // reload at step n + k is at the same overlap as unload at step 2n - k
    double worst = 0.0;
    for (int k = 1; k < n; ++k) worst = std::max(worst, std::fabs(t.F[2 * n + k - 1] - t.F[2 * n - k - 1]));
    CHECK(worst / Fpeak < 50 * rel_tol_of<T>());
    // the residual overlap: force zero below it, positive above; delta_p from the state agrees
    const double dp = t.delta_p[2 * n - 1];
    CHECK(dp > 0.0);
    CHECK(dp < dmax);
    for (int k = n; k < 2 * n; ++k) {
      if (path[k] < dp * (1 - 1e-4)) CHECK(t.F[k] == 0.0);
      if (path[k] > dp * (1 + 1e-4)) CHECK(t.F[k] > 0.0);
    }
    CHECK(dp > last_residual);
    last_residual = dp;
    // unloading is monotone, and loading past delta_max raises the force above Fpeak
    for (int k = n; k < 2 * n; ++k) CHECK(t.F[k] <= t.F[k - 1] * (1 + 10 * rel_tol_of<T>()) + 1e-30);
    CHECK(t.F.back() > Fpeak);
  }
}

TEMPLATE_LIST_TEST_CASE("MDR ellipse guards: force, gap and width at the ends of their domains", "[mdr][guard]",
                        BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  Kokkos::View<double*, D> o("o", 16);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        const T E = 1, A = 4, B = 2;
        o(0) = mdr_ellipse_force(E, A, B, T(0));        // d = 0
        o(1) = mdr_ellipse_force(E, A, B, T(-1));       // d < 0
        o(2) = mdr_ellipse_force(E, A, B, A);           // fully submerged: E A B pi / 4
        o(3) = mdr_ellipse_force(E, A, B, T(10) * A);   // beyond: clamped
        o(4) = mdr_ellipse_force(E, A, B, T(0.5) * A);  // equator: E A B pi / 8 (F_max, (32))
        // both sides of the series/direct switch at theta = 0.25 (x = sin^2(0.125))
        const T xs = math::sin(T(0.125)) * math::sin(T(0.125));
        o(5) = mdr_ellipse_force(E, A, B, A * xs * T(1 - 1e-6));
        o(6) = mdr_ellipse_force(E, A, B, A * xs * T(1 + 1e-6));
        o(7) = mdr_ellipse_gap(A, B, T(0.5) * B);              // a = B/2: A/2
        o(8) = mdr_ellipse_gap(A, B, B);                       // a > B/2: clamped
        o(9) = mdr_ellipse_gap(A, B, T(1e-4));                 // small a: A a^2 / B^2
        o(10) = mdr_ellipse_contact_radius(A, B, T(0.5) * A);  // B/2
        o(11) = mdr_ellipse_contact_radius(A, B, A);           // beyond the equator: B/2
        o(12) = mdr_ellipse_contact_radius(A, B, T(-1));       // no contact
        o(13) = mdr_ellipse_gap_slope(A, B, T(0.5) * B);       // infinite slope reported as 0
        o(14) = mdr_ellipse_force(E, A, B, T(1e-30));          // tiny depth: no underflow to NaN
      });
  auto h = to_host(o);
  const double tol = sizeof(T) >= 8 ? 1e-13 : 1e-5;
  CHECK(h(0) == 0.0);
  CHECK(h(1) == 0.0);
  CHECK(h(2) == Approx(4 * 2 * M_PI / 4).epsilon(tol));
  CHECK(h(3) == Approx(h(2)).epsilon(tol));
  CHECK(h(4) == Approx(4 * 2 * M_PI / 8).epsilon(tol));
  CHECK(std::fabs(h(6) - h(5)) / h(5) < 4e-6 + tol);  // continuous across the switch (slope 1.5)
  CHECK(h(7) == Approx(2.0).epsilon(tol));
  CHECK(h(8) == Approx(2.0).epsilon(tol));
  CHECK(h(9) == Approx(4 * 1e-8 / 4).epsilon(1e-6));
  CHECK(h(10) == Approx(1.0).epsilon(tol));
  CHECK(h(11) == Approx(1.0).epsilon(tol));
  CHECK(h(12) == 0.0);
  CHECK(h(13) == 0.0);
  CHECK(std::isfinite(h(14)));
  CHECK(h(14) >= 0.0);
}

TEMPLATE_LIST_TEST_CASE("MDR plastic shape guards: z_R -> 0, delta_max past the equator, recovery ratio floor",
                        "[mdr][guard]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const auto c = side_constants<T>(1.0, kNu, 1.0 / 25.0);
  Kokkos::View<double**, Kokkos::LayoutRight, D> o("o", 6, 6);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        const T R = 1;
        const T dY = c.x_yield * R;
        const T cA = constants<T>::pi * (dY * dY - dY * R);
        const T dms[6] = {T(0.3), T(0.75), T(0.95), T(1.0), T(1.5), T(3.0)};
        for (int k = 0; k < 6; ++k) {
          const MdrPlasticShape<T> s = mdr_plastic_shape(c, dms[k], R, cA);
          o(k, 0) = s.a_max;
          o(k, 1) = s.A;
          o(k, 2) = s.ratio;
          o(k, 3) = s.delta_p;
          o(k, 4) = s.ratio_floored ? 1 : 0;
          // the force along an unloading from there stays finite
          MdrSideState<T> st;
          st.delta_o_max = dms[k];
          st.yielded = 1;
          st.c_A = cA;
          const MdrSideResult<T> r = mdr_side_force<true, false>(c, T(0), T(1), dms[k] * T(0.9), R, T(0), st);
          o(k, 5) = r.F;
        }
      });
  auto h = to_host(o);
  for (int k = 0; k < 6; ++k) {
    for (int q = 0; q < 6; ++q) CHECK(std::isfinite(h(k, q)));
    CHECK(h(k, 0) > 0.0);
    CHECK(h(k, 2) >= 0.01 * (1 - 1e-6));
    CHECK(h(k, 5) >= 0.0);
  }
  CHECK(h(0, 4) == 0);  // 0.3 R: unguarded
  CHECK(h(1, 4) == 0);  // 0.75 R: unguarded
  CHECK(h(5, 4) == 1);  // 3 R: floored
  // a_max is kept at the equator value past delta_max = R
  CHECK(h(4, 0) == Approx(h(3, 0)).epsilon(1e-5));
  // the residual overlap stays below delta_max
  for (int k = 0; k < 6; ++k) CHECK(h(k, 3) < (k == 0 ? 0.3 : 3.0));
}

TEST_CASE("MDR yield ratio: root of the yield equation, never-yield cases", "[mdr][guard][yield]") {
  for (double r : {6.25 / 0.91, 12.5, 100.0, 1e4, 1e6}) {
    for (auto onset : {MdrYieldOnset::hertz_40, MdrYieldOnset::elastic_law}) {
      const double x = mdr_yield_ratio(r, 1.0, onset);
      REQUIRE(std::isfinite(x));
      const double pY = 1.75 * std::exp(-4.4 * x) + 1.0;
      double p;
      if (onset == MdrYieldOnset::hertz_40) {
        p = 4.0 * r / (3.0 * M_PI) * std::sqrt(x);
      } else {
        p = mdr_ellipse_force(r, 4.0, 2.0, x) / (M_PI * x);
      }
      CHECK(p == Approx(pY).epsilon(1e-10));
    }
  }
  CHECK(std::isinf(mdr_yield_ratio(10.0, std::numeric_limits<double>::infinity(), MdrYieldOnset::elastic_law)));
  // E_eff/Y = 1: the ellipse's mean pressure never reaches p_Y >= Y
  CHECK(std::isinf(mdr_yield_ratio(1.0, 1.0, MdrYieldOnset::elastic_law)));
  // options and materials are validated on the host
  MdrOptions bad;
  bad.xi = 2;
  CHECK_THROWS_AS(bad.validate(), ParameterError);
  bad = MdrOptions{};
  bad.radius_cap = 0.5;
  CHECK_THROWS_AS(bad.validate(), ParameterError);
  CHECK_THROWS_AS(mdr_side_constants<double>(rigid_wall_material(), MdrYieldOnset::elastic_law), ParameterError);
  CHECK_THROWS_AS(mdr_side_constants<double>(mdr_material(-1.0, 0.3, 1.0), MdrYieldOnset::elastic_law), ParameterError);
}

// Callers that solve for no pair split (the geometric split, the bulk response, walls, the
// equal-pair split of one material) skip the side's stiffness (mdr_side_force's with_stiffness =
// false: its two divisions per side). Nothing else may change: the force, the width, the area and
// the advanced state are bit for bit those of the full evaluation on a path through every regime
// (elastic, yield, plastic loading, unloading, reloading, separation), with and without adhesion;
// the stiffness is 0 without it and positive with it wherever the side touches.
template <class D, class T, bool Adhesive>
void check_side_without_stiffness(double gamma) {
  const double R = 1e-3;
  const auto c = side_constants<T>(1e8, kNu, 5e5);  // E/Y 200
  std::vector<double> path;
  for (int k = 1; k <= 40; ++k) path.push_back(k * 2e-4 * R);     // elastic, yield, plastic loading
  for (int k = 39; k >= -5; --k) path.push_back(k * 1.9e-4 * R);  // unloading past separation
  for (int k = 0; k <= 30; ++k) path.push_back(k * 2.1e-4 * R);   // reloading below delta_max
  const int n = static_cast<int>(path.size());
  Kokkos::View<T*, D> dv("path", n);
  auto hd = Kokkos::create_mirror_view(dv);
  for (int k = 0; k < n; ++k) hd(k) = T(path[k]);
  Kokkos::deep_copy(dv, hd);
  Kokkos::View<int*, D> bad("bad", 3);  // differing results, a stiffness not 0, touching without stiffness
  const T g = T(gamma), Rt = T(R);
  Kokkos::parallel_for(
      "mdr_test::side_without_stiffness", Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        MdrSideState<T> s_full, s_lean;
        for (int k = 0; k < n; ++k) {
          const MdrSideResult<T> full = mdr_side_force<true, Adhesive>(c, g, T(1), dv(k), Rt, T(0), s_full);
          const MdrSideResult<T> lean =
              mdr_side_force<true, Adhesive>(c, g, T(1), dv(k), Rt, T(0), s_lean, T(1), false);
          const bool same = full.F == lean.F && full.a == lean.a && full.area == lean.area && full.A == lean.A &&
                            full.B == lean.B && full.d1De == lean.d1De && full.delta_max == lean.delta_max &&
                            full.plastic == lean.plastic && full.loading == lean.loading &&
                            full.adhesion_state == lean.adhesion_state && s_full.delta_p == s_lean.delta_p &&
                            s_full.delta_o_max == s_lean.delta_o_max && s_full.yielded == s_lean.yielded &&
                            s_full.c_A == s_lean.c_A && s_full.a_adh == s_lean.a_adh;
          if (!same) bad(0) += 1;
          if (lean.stiffness != T(0)) bad(1) += 1;
          if (full.a > T(0) && !(full.stiffness > T(0) || (full.plastic && full.loading))) bad(2) += 1;
        }
      });
  const auto h = test::to_host(bad);
  CHECK(h(0) == 0);
  CHECK(h(1) == 0);
  CHECK(h(2) == 0);
}

TEMPLATE_LIST_TEST_CASE("MDR side: without the stiffness, the same force, width and state bit for bit", "[mdr][side]",
                        BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  check_side_without_stiffness<D, T, false>(0.0);
  check_side_without_stiffness<D, T, true>(0.05);  // adhesion: the tension branch below delta_p
}

// The stored plastic shape (MdrSideState::shape_*): below delta_max at the radius it was computed
// for, a yielded side takes its shape from the state instead of recomputing it. Along a path
// through yield, plastic loading, unloading, reloading and a growth of R (delta_max shifts by (19)
// and the key moves), every result and the advanced state must be bit for bit those of a state
// whose store is emptied before each step (shape_R = 0: recomputed every time), with and without
// the stiffness. And the store must be what the hits read: with its A scaled, exactly the steps
// predicted to hit (same R, same delta_max, unloading or without the stiffness) change their
// delta_1D^e (A/2 + (delta - delta_max)/r, (35); the force is 0 below delta_p, so not the force).
template <class D, class T>
void check_stored_shape(bool with_stiffness) {
  const double R0 = 1e-3;
  const auto c = side_constants<T>(1e8, kNu, 5e5);  // E/Y 200
  std::vector<double> path, radius;
  for (int k = 1; k <= 40; ++k) path.push_back(k * 2e-4 * R0);     // elastic, yield, plastic loading
  for (int k = 39; k >= 10; --k) path.push_back(k * 1.9e-4 * R0);  // unloading
  for (int k = 10; k <= 30; ++k) path.push_back(k * 2.1e-4 * R0);  // reloading below delta_max
  const int grown_from = static_cast<int>(path.size());
  for (int k = 30; k >= 20; --k) path.push_back(k * 2.1e-4 * R0);  // unloading at a grown radius
  const int n = static_cast<int>(path.size());
  for (int k = 0; k < n; ++k) radius.push_back(k < grown_from ? R0 : R0 * 1.002);
  Kokkos::View<T*, D> dv("path", n), rv("radius", n);
  auto hd = Kokkos::create_mirror_view(dv);
  auto hr = Kokkos::create_mirror_view(rv);
  for (int k = 0; k < n; ++k) {
    hd(k) = T(path[k]);
    hr(k) = T(radius[k]);
  }
  Kokkos::deep_copy(dv, hd);
  Kokkos::deep_copy(rv, hr);
  // differing results, predicted hits, probes whose delta_1D^e changed on a predicted hit / a miss
  Kokkos::View<int*, D> count("count", 4);
  const T R0t = T(R0);
  Kokkos::parallel_for(
      "mdr_test::stored_shape", Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        MdrSideState<T> s_kept, s_fresh;
        for (int k = 0; k < n; ++k) {
          const T R = rv(k), growth = R - R0t, delta = dv(k);
          // the step's delta_max, (19): loading moves it (and misses the store)
          const bool loading = delta - growth >= s_kept.delta_o_max;
          const T delta_max = (loading ? delta - growth : s_kept.delta_o_max) + growth;
          const bool hit = s_kept.yielded != T(0) && s_kept.shape_R == R && s_kept.shape_delta_max == delta_max &&
                           !(with_stiffness && loading);
          MdrSideState<T> s_probe = s_kept;
          s_probe.shape_A *= T(1.5);
          s_fresh.shape_R = T(0);
          const MdrSideResult<T> kept =
              mdr_side_force<true, false>(c, T(0), T(1), delta, R, growth, s_kept, T(1), with_stiffness);
          const MdrSideResult<T> fresh =
              mdr_side_force<true, false>(c, T(0), T(1), delta, R, growth, s_fresh, T(1), with_stiffness);
          const MdrSideResult<T> probe =
              mdr_side_force<true, false>(c, T(0), T(1), delta, R, growth, s_probe, T(1), with_stiffness);
          const bool same = kept.F == fresh.F && kept.a == fresh.a && kept.area == fresh.area && kept.A == fresh.A &&
                            kept.B == fresh.B && kept.d1De == fresh.d1De && kept.delta_max == fresh.delta_max &&
                            kept.stiffness == fresh.stiffness && kept.plastic == fresh.plastic &&
                            kept.loading == fresh.loading && kept.ratio_floored == fresh.ratio_floored &&
                            s_kept.delta_p == s_fresh.delta_p && s_kept.delta_o_max == s_fresh.delta_o_max &&
                            s_kept.yielded == s_fresh.yielded && s_kept.c_A == s_fresh.c_A &&
                            s_kept.shape_A == s_fresh.shape_A && s_kept.shape_a_max == s_fresh.shape_a_max &&
                            s_kept.shape_ratio == s_fresh.shape_ratio;
          if (!same) count(0) += 1;
          if (hit) count(1) += 1;
          if (probe.d1De != kept.d1De) count(hit ? 2 : 3) += 1;
        }
      });
  const auto h = test::to_host(count);
  INFO("with the stiffness: " << with_stiffness << ", predicted hits " << h(1));
  CHECK(h(0) == 0);
  CHECK(h(1) >= 50);    // the unloading and reloading steps below delta_max (61 of them)
  CHECK(h(2) == h(1));  // every predicted hit read the stored A ...
  CHECK(h(3) == 0);     // ... and no other step did
}

TEMPLATE_LIST_TEST_CASE("MDR side: the stored plastic shape gives a fresh shape's bits, and the hits read it",
                        "[mdr][side]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  check_stored_shape<D, T>(true);
  check_stored_shape<D, T>(false);
}
