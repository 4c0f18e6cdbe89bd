// MDR at the edges found after the pair split was fixed (docs/stability.md): the area terms near and past
// delta = R, the radius-growth guards with the smallest floors `MdrOptions` accepts, and pairs of
// materials with very unequal surface energies. Each drives a guarded expression to its edge and
// asserts finite, bounded results and the physical invariants that still hold there.
#include "contact_stepper.hpp"
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace epac;
using namespace epac::test;

// (36) takes min(delta_max, R) and (42) is pi (2 delta R - delta^2) + c_A, whose delta-part peaks
// at delta = R; (33)-(35) floor z_R and the recovery ratio. One side is loaded through R to 1.6 R
// and unloaded past separation, elastic and at E/Y 6.25 and 1e4, float and double.
TEMPLATE_LIST_TEST_CASE("MDR edges: one side loaded through delta = R to 1.6 R and back stays finite and ordered",
                        "[mdr][edge]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double R = 1e-3, E = 1e9;
  for (double EY : {6.25, 1e4, kInf}) {
    INFO("E/Y = " << EY);
    const auto c = side_constants<T>(E, kNu, std::isfinite(EY) ? E / EY : kInf);  // E/Y = inf: elastic
    std::vector<double> path;
    append_ramp(path, 0.0, 0.9 * R, 300);
    append_ramp(path, 0.9 * R, 1.1 * R, 400);  // fine steps across delta = R
    append_ramp(path, 1.1 * R, 1.6 * R, 200);
    const int n_load = static_cast<int>(path.size());  // the unloading starts after it
    append_ramp(path, 1.6 * R, -0.1 * R, 400);
    const SideTrace t = run_side_path<D, T, true, false>(c, 0.0, 1.0, R, path);
    int floored = 0;
    for (int k = 0; k < t.size(); ++k) {
      INFO("step " << k << ", delta/R " << t.delta[k] / R);
      REQUIRE(std::isfinite(t.F[k]));
      REQUIRE(std::isfinite(t.area[k]));
      REQUIRE(std::isfinite(t.delta_p[k]));
      CHECK(t.F[k] >= 0.0);
      CHECK(t.area[k] >= 0.0);
      CHECK(t.delta_p[k] <= t.delta_max[k]);  // the residual never passes the largest overlap
      floored += t.floored[k];
      // loading: never softer up to 0.9 R. Beyond it the fully plastic force pi p_Y a_max^2 may
      // fall (p_Y of (16) with (21) falls with delta_max/R while a_max^2 of (36) flattens at R):
      // the published law, from about 0.94 R at these E/Y
      if (k > 0 && k < 300) CHECK(t.F[k] >= t.F[k - 1] * (1 - 1e-6));
      if (k > n_load) CHECK(t.F[k] <= t.F[k - 1] * (1 + 1e-6));  // unloading: never harder
    }
    // the area of (42) is continuous through delta = R (its delta-part peaks there)
    for (int k = 301; k < 700; ++k) CHECK(std::fabs(t.area[k] - t.area[k - 1]) <= 0.01 * t.area[k]);
    CHECK(t.F.back() == 0.0);                   // past separation
    if (std::isfinite(EY)) CHECK(floored > 0);  // the recovery-ratio guard of (35) was reached
  }
}

// Growth guards with the smallest floors the options accept (denominator_floor, volume_floor ->
// 1e-9): die compaction pushed to 0.7 R_o per flat. The denominator of (37) may then come within
// 1e-9 of zero: R must still be finite, capped, non-decreasing and V positive.
TEMPLATE_LIST_TEST_CASE("MDR edges: radius growth with tiny denominator and volume floors stays finite",
                        "[mdr][edge][growth]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  MdrOptions opt;
  opt.denominator_floor = 1e-9;
  opt.volume_floor = 1e-9;
  for (double EY : {6.25, 20.0, 1e3}) {
    INFO("E/Y = " << EY);
    const M model = M::create({mdr_material(1e9, kNu, 1e9 / EY), rigid_wall_material()}, opt);
    std::array<int, kMdrGuardCount> guards{};
    std::vector<double> path;
    append_ramp(path, 0.0, 0.7e-3, 700);
    append_ramp(path, 0.7e-3, -0.05e-3, 200);
    const FlatTrace t = run_flats<M, D>(model, 1e-3, path, true, &guards);
    for (size_t k = 0; k < t.R.size(); ++k) {
      REQUIRE(std::isfinite(t.F_primary[k]));
      REQUIRE(std::isfinite(t.F_secondary[k]));
      REQUIRE(std::isfinite(t.R[k]));
      CHECK(t.R[k] <= 1.5e-3 * (1 + 1e-6));
      CHECK(t.V[k] > 0.0);
      if (k > 0) CHECK(t.R[k] >= t.R[k - 1]);  // R never decreases
    }
    INFO("guard hits: denominator " << guards[0] << ", cap " << guards[1] << ", volume " << guards[2]);
    CHECK(t.R.back() > 1e-3);  // it did grow
  }
}

// Pair of materials whose surface energies differ by up to 1e9 (the pair's Delta gamma is their
// geometric mean, material.hpp; each side's share is Delta gamma E*/E_eff,s): a plastic load, an
// unload into tension, a jump far apart and a re-approach, unequal radii and moduli. Finite,
// adhesive, detached (exactly 0) once far apart, and a re-approach is a new compressive contact.
TEMPLATE_LIST_TEST_CASE("MDR edges: pairs with very unequal surface energies stay finite and detach",
                        "[mdr][edge][adhesion]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kAdhesion>, D>;
  const double R0 = 1e-3, R1 = 4e-3;
  for (double ratio : {1e3, 1e6, 1e9}) {
    for (double Eratio : {1.0, 100.0}) {
      const double E0 = 1e8, E1 = 1e8 * Eratio;
      // the larger energy at the accepted limit E R of the softer material's scale
      const double g_hi = 0.1 * E0 * R0, g_lo = g_hi / ratio;
      INFO("surface energy ratio " << ratio << ", modulus ratio " << Eratio);
      const Material a = mdr_material(E0, kNu, E0 / 20, g_hi), b = mdr_material(E1, 0.25, E1 / 50, g_lo);
      const M model = M::create({a, b});
      ContactStepper<M> s(model, R0, R1, 0, 1);
      std::vector<double> path;
      append_ramp(path, 0.0, 0.3 * R0, 150);
      append_ramp(path, 0.3 * R0, -0.05 * R0, 3500);  // 1e-4 R0 steps: the tensile range is ~4e-3 R0
      double max_tension = 0;
      // the first step of the unload whose force is below 1e-5 of the peak: past it the force is
      // tension or a residual of rounding (+-2e-15 N in double, +5e-7 N in float, of either sign)
      std::size_t first_released = 0;
      double peak = 0;
      for (std::size_t k = 0; k < path.size(); ++k) {
        const double F = s.step(path[k]);
        REQUIRE(std::isfinite(F));
        REQUIRE(s.radii_finite());
        max_tension = std::max(max_tension, -F);
        peak = std::max(peak, F);
        if (k > 150 && F <= 1e-5 * peak && first_released == 0) first_released = k;
      }
      // Adhesion acted: the largest tension against a JKR pull-off with the pair's Delta gamma
      // (sqrt(g_hi g_lo), material.hpp) on R*, 1.5 pi Delta gamma R*. With equal moduli it is
      // above that; with the stiff side 100 times stiffer the pair lets go when that side's
      // share of Delta gamma (E*/E_eff,s, about 1/100) does, at 2.6% of it (measured, every
      // energy ratio). 1% is far above rounding (1e-15 N in double, 6e-8 N in float, which a mere
      // sign check once passed on).
      const double pull_off = 1.5 * M_PI * std::sqrt(g_hi * g_lo) * R0 * R1 / (R0 + R1);
      // Where the unload's 1e-4 R0 steps jump over the whole tensile window (stiff side 100 times
      // stiffer, energies 1e6 apart: 26 nm wide; at 1e9 below 1 nm), the same path is replayed to
      // the step before the force fell below 1e-5 of the peak, and the two coarse steps after it
      // are walked again in 2e4 steps of 1e-11 m.
      if (max_tension < 0.01 * pull_off) {
        REQUIRE(first_released > 150);
        REQUIRE(first_released + 1 < path.size());
        ContactStepper<M> fine(model, R0, R1, 0, 1);
        for (std::size_t k = 0; k < first_released; ++k) (void)fine.step(path[k]);
        const double d0 = path[first_released - 1], d1 = path[first_released + 1];
        for (int k = 1; k <= 20000; ++k) {
          const double F = fine.step(d0 + (d1 - d0) * k / 20000.0);
          REQUIRE(std::isfinite(F));
          max_tension = std::max(max_tension, -F);
        }
      }
      INFO("largest tension " << max_tension << " N; JKR pull-off on R* " << pull_off << " N");
      CHECK(max_tension > (Eratio == 1.0 ? 1.0 : 0.01) * pull_off);
      const double F_far = s.step(-200 * R0);
      CHECK(F_far == 0.0);
      const double F_back = s.step(0.01 * R0);
      REQUIRE(std::isfinite(F_back));
      CHECK(F_back > 0.0);
    }
  }
}
