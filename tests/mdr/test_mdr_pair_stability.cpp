// MDR pairs stay finite and conservative where the old pair split did not (MDR finite for every accepted input, docs/stability.md):
// the split's interpolation stays in [0, 1] and never throws a side beyond its residual or above
// its height at dmax; the two reproductions of the issue; closed elastic cycles of unequal pairs
// return at most the work put in; the yielded_contacts growth rule does not ratchet elastic contacts.
#include "contact_stepper.hpp"
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace epac;
using namespace epac::test;

namespace {
using GrowthEffects = Effects<kPlasticity | kAdhesion | kRadiusGrowth>;

// Work put in (loading steps) and returned (unloading steps) along a path, trapezoid rule.
struct CycleWork {
  double in = 0, out = 0;
};
CycleWork cycle_work(const std::vector<double>& delta, const std::vector<double>& F) {
  CycleWork w;
  for (size_t k = 1; k < F.size(); ++k) {
    const double dw = 0.5 * (F[k] + F[k - 1]) * (delta[k] - delta[k - 1]);
    (dw > 0 ? w.in : w.out) += std::fabs(dw);
  }
  return w;
}
}  // namespace

TEMPLATE_TEST_CASE("MDR pair split: continuous, sums to delta, bounded by residuals and heights", "[mdr][pair][guard]",
                   double, float) {
  using T = TestType;
  const double eps = std::numeric_limits<T>::epsilon();
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int cases = 0, beyond_dmax_residuals = 0;
  for (int c = 0; c < 3000; ++c) {
    const double R0 = std::pow(10.0, -2 + 2 * u(rng)), R1 = R0 * std::pow(10.0, -2 + 4 * u(rng));
    const double dmax = (R0 + R1) * 0.9 * u(rng) + 1e-6 * R0;
    // residuals anywhere in [0, 1.2 dmax] each: includes sums >= dmax (no elastic recovery) and a
    // side whose residual exceeds its height (grown radius)
    const double dp0 = c % 4 == 0 ? 0.0 : 1.2 * dmax * u(rng), dp1 = c % 4 == 0 ? 0.0 : 1.2 * dmax * u(rng);
    if (dp0 + dp1 >= dmax) ++beyond_dmax_residuals;
    const T h0 = mdr_side0_height(T(dmax), T(R0), T(R1)), h1 = T(dmax) - h0;
    const double e0 = std::min(dp0, double(h0)), e1 = std::min(dp1, double(h1));
    MdrSideOverlaps<T> prev{};
    double dprev = 0;
    const int n = 400;
    for (int k = 0; k <= n; ++k) {
      const double delta = dmax * (1.2 - 1.5 * double(k) / n);  // dmax * 1.2 down to -0.3 dmax
      const double dcl = std::min(delta, dmax);
      const MdrSideOverlaps<T> s = mdr_split_overlap(T(dcl), T(dmax), T(R0), T(R1), T(dp0), T(dp1));
      const double tol = 64 * eps * (dmax + R0 + R1);
      INFO("R0 " << R0 << " R1 " << R1 << " dmax " << dmax << " dp " << dp0 << " " << dp1 << " delta " << dcl);
      REQUIRE(std::isfinite(double(s.d0)));
      REQUIRE(std::isfinite(double(s.d1)));
      CHECK(std::fabs(double(s.d0) + double(s.d1) - dcl) <= tol);  // the flat stays between the spheres
      // never above the height at dmax (no side reloads while the pair unloads)
      CHECK(double(s.d0) <= double(h0) + tol);
      CHECK(double(s.d1) <= double(h1) + tol);
      if (dcl >= e0 + e1) {
        // above the summed residuals: no side beyond its residual
        CHECK(double(s.d0) >= e0 - tol);
        CHECK(double(s.d1) >= e1 - tol);
      } else {
        // below: both sides below their residuals, by at most the distance below the sum
        CHECK(double(s.d0) <= e0 + tol);
        CHECK(double(s.d1) <= e1 + tol);
        CHECK(double(s.d0) >= e0 - (e0 + e1 - dcl) - tol);
        CHECK(double(s.d1) >= e1 - (e0 + e1 - dcl) - tol);
      }
      // continuous: a side moves at most a bounded multiple of the overlap step (Lipschitz)
      if (k > 0) {
        const double step = std::fabs(dcl - dprev);
        CHECK(std::fabs(double(s.d0) - double(prev.d0)) <= 4 * step + tol);
        CHECK(std::fabs(double(s.d1) - double(prev.d1)) <= 4 * step + tol);
      }
      prev = s;
      dprev = dcl;
    }
    ++cases;
  }
  CHECK(beyond_dmax_residuals > 300);
}

TEMPLATE_LIST_TEST_CASE(
    "MDR pair with growth, reported NaN reproduction 1: one step to 0.8 R_small, then unload (radii 0.1, 1 mm)",
    "[mdr][pair][growth][stability]", BackendsAndScalars) {
  // Old split: NaN at unloading step 68 (double) / 20 (float): the residuals summed to more than
  // dmax and the floored denominator threw a side 1e7 R deep.
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, GrowthEffects, D>;
  const double E = 1e8, Rs = 1e-4, Rl = 1e-3;
  const M model = M::create({mdr_material(E, 0.3, E / 20.0, 0.05), rigid_wall_material()});
  std::vector<double> path{0.8 * Rs};
  for (int k = 1; k <= 120; ++k) path.push_back((0.8 - 0.01 * k) * Rs);  // to -0.4 R_small
  const PairTrace t = run_pair_path<M, D>(model, Rs, Rl, 0, path);
  INFO("first non-finite step " << t.first_non_finite);
  CHECK(t.finite);
  double peak = 0;
  for (double f : t.F) peak = std::max(peak, std::fabs(f));
  CHECK(peak > 0);
  for (size_t k = 0; k < t.F.size(); ++k) {
    CHECK(t.R0[k] <= 1.5 * Rs * (1 + 1e-6));
    CHECK(t.R1[k] <= 1.5 * Rl * (1 + 1e-6));
    // once unloading, nothing grows (growth feeds on plastic loading only): the force only falls
    if (k >= 2) CHECK(t.F[k] <= t.F[k - 1] * (1 + 1e-9) + 1e-30);
    // the first unloading step carries the jump's growth: the small particle's side sphere and its
    // apparent overlap both grew by R - R_o (MDR (19)), so it pushes harder than the jump itself,
    // by 14.6% (default split; 1.7% when a balance solve moved the flat off the grown side, 31%
    // when the sides' spheres followed R* of the grown radii): bound 1.25, a guard on the measured value
    CHECK(t.F[k] <= 1.25 * t.F[0]);
  }
}

TEMPLATE_LIST_TEST_CASE("MDR pair with growth, reported NaN reproduction 2: smooth path, soft elastic partner",
                        "[mdr][pair][growth][stability]", BackendsAndScalars) {
  // E 1e7 Pa, E/Y 42000, Delta gamma 144 J/m^2 against an elastic sphere of E 1.4e5 Pa; radii 2.6
  // and 11 mm; 200 steps to 0.4 R, unload by 0.002 R per step (old split: NaN at step 325 while
  // the spheres still overlapped). Both radius assignments.
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, GrowthEffects, D>;
  const M model = M::create({mdr_material(1e7, 0.3, 1e7 / 42000.0, 144.0), mdr_material(1.4e5, 0.3, kInf, 144.0)});
  for (int swap = 0; swap < 2; ++swap) {
    const double Ra = swap ? 11e-3 : 2.6e-3, Rb = swap ? 2.6e-3 : 11e-3, R = 2.6e-3;
    std::vector<double> path;
    append_ramp(path, 0.0, 0.4 * R, 200);
    append_ramp(path, 0.4 * R, -0.2 * R, 300);
    const PairTrace t = run_pair_path<M, D>(model, Ra, Rb, 1, path);
    INFO("swap " << swap << ", first non-finite step " << t.first_non_finite);
    CHECK(t.finite);
    for (size_t k = 0; k < t.F.size(); ++k) {
      CHECK(t.R0[k] <= 1.5 * Ra * (1 + 1e-6));
      CHECK(t.R1[k] <= 1.5 * Rb * (1 + 1e-6));
    }
  }
}

TEMPLATE_LIST_TEST_CASE("MDR elastic pair, unequal radii and moduli: a closed cycle returns at most the work put in",
                        "[mdr][pair][energy]", BackendsAndScalars) {
  // Old split: unloading linear in delta, loading on the radical plane: the force was two-valued
  // and a cycle returned +0.12% of its work (unchanged with finer steps). Now the elastic unloading
  // path is the loading path, so the force is single-valued: returned = put in to round-off.
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  for (double ratio : {1.0, 3.0, 100.0})
    for (double Eratio : {1.0, 7.0, 1e3}) {
      const double E = 1e8, Rs = 1e-4, Rl = ratio * Rs;
      const M model = M::create({mdr_material(E, 0.3, kInf), mdr_material(E * Eratio, -0.2, kInf)});
      std::vector<double> path{0.0};
      append_ramp(path, 0.0, 0.3 * Rs, 300);
      append_ramp(path, 0.3 * Rs, 0.1 * Rs, 200);
      append_ramp(path, 0.1 * Rs, 0.5 * Rs, 400);
      append_ramp(path, 0.5 * Rs, -0.05 * Rs, 550);
      for (int m1 : {0, 1}) {
        const PairTrace t = run_pair_path<M, D>(model, Rs, Rl, m1, path);
        const CycleWork w = cycle_work(t.delta, t.F);
        INFO("radius ratio " << ratio << ", modulus ratio " << Eratio << ", m1 " << m1 << ": in " << w.in << ", out "
                             << w.out << ", relative " << (w.out - w.in) / w.in);
        CHECK(t.finite);
        REQUIRE(w.in > 0);
        CHECK(w.out <= w.in * (1 + 1e-9));
        CHECK(t.R0.back() == double(T(Rs)));  // elastic: no growth
      }
    }
}

TEMPLATE_LIST_TEST_CASE("MDR growth_rule yielded_contacts: an elastic sphere between flats does not ratchet",
                        "[mdr][growth][energy]", BackendsAndScalars) {
  // Old rule: every touching side grew R once delta/R exceeded ~0.02 and R never shrank, so a
  // closed cycle of a non-yielding, non-adhesive sphere returned 0.63% more work than it took.
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  MdrOptions opt;
  opt.growth_rule = MdrGrowthRule::yielded_contacts;
  const M model = M::create({mdr_material(1.0, 0.3, kInf), rigid_wall_material()}, opt);
  std::vector<double> path{0.0};
  append_ramp(path, 0.0, 0.15, 600);
  append_ramp(path, 0.15, 0.05, 400);
  append_ramp(path, 0.05, 0.2, 600);
  append_ramp(path, 0.2, -0.01, 840);  // one grid (2.5e-4): each segment crossed up and down
  const FlatTrace t = run_flats<M, D>(model, 1.0, path, false);
  const CycleWork w = cycle_work(t.delta_o, t.F_primary);
  INFO("in " << w.in << ", out " << w.out << ", relative " << (w.out - w.in) / w.in);
  REQUIRE(w.in > 0);
  CHECK(w.out <= w.in * (1 + 1e-9));
  CHECK(t.R.back() == 1.0);  // no yield: no growth
}

// The balanced split (mdr_pair_balance.hpp): the flat sits where lambda_0 F_0 = lambda_1 F_1, so
// the mean force is a positive constant combination of the sides' forces along the sides' own
// paths and a closed cycle of a yielded unequal pair cannot return more than it took (the
// geometric split with the mean force did on ~1% of random cycles, up to 19% of their work).
// The default split (equal_pair, detail/mdr_pair_equal.hpp) balances the sides' forces themselves,
// F_0 = F_1 (lambda_s = 1/2): the same identities, the same argument.
TEMPLATE_LIST_TEST_CASE("MDR pair: the flat balances the sides' scaled forces; yielded unequal pairs dissipate",
                        "[mdr][pair][energy]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity>, D>;
  // balance tolerance: the solve stops at a few ulps of the scaled forces or of the overlaps
  const double tol = sizeof(T) >= 8 ? 1e-9 : 2e-3;
  // identities evaluated twice (the force pass and the outputs re-solve from the stored state):
  // the balance tolerance (mdr_balance_tolerance: 1.4e-14 double, 9.5e-7 float) of the scaled
  // forces, times the stiffness ratio of the sides (up to ~500 here) in the stiff side's force
  const double same = sizeof(T) >= 8 ? 1e-11 : 1e-3;
  struct Case {
    double R0, R1, E0, E1, Y0, Y1;
  };
  const Case cases[] = {
      {1e-3, 1e-3, 1e8, 1e8, 2e6, kInf},  // equal radii, one side elastic
      {1e-3, 3e-3, 1e8, 1e8, 2e6, 2e6},   // radius ratio 3, one material
      {1e-3, 3e-2, 1e8, 3e9, 2e6, 1e7},   // radius ratio 30, modulus ratio 30
      {2e-3, 1e-4, 5e9, 1e7, kInf, 1e5},  // small soft plastic on large stiff elastic
      {1e-3, 1e-3, 1e8, 1e8, 1e6, 1e6},   // equal spheres: delta/2 each, no solve
  };
  for (const MdrPairSplit split : {MdrPairSplit::balanced, MdrPairSplit::equal_pair})
    for (const Case& c : cases) {
      const bool equal_pair = split == MdrPairSplit::equal_pair;
      CAPTURE(equal_pair, c.R0, c.R1, c.E0, c.E1, c.Y0, c.Y1);
      const Material a = mdr_material(c.E0, 0.3, c.Y0), b = mdr_material(c.E1, 0.25, c.Y1);
      MdrOptions opt;
      opt.pair_split = split;
      const M model = M::create({a, b}, opt);
      const double Ea = c.E0 / (1 - 0.09), Eb = c.E1 / (1 - 0.0625);
      const double lam0 = equal_pair ? 0.5 : c.R0 * Eb / ((c.R0 + c.R1) * (Ea + Eb)),
                   lam1 = equal_pair ? 0.5 : c.R1 * Ea / ((c.R0 + c.R1) * (Ea + Eb));
      const double Rmin = std::min(c.R0, c.R1);
      // one grid of 5e-4 Rmin: load 0.3, unload 0.1, reload 0.4, unload to a gap (each segment
      // crossed as often up as down)
      const double h = 5e-4 * Rmin;
      std::vector<double> path;
      auto walk = [&](double from, double to) {
        const int n = static_cast<int>(std::lround(std::fabs(to - from) / h));
        for (int k = 1; k <= n; ++k) path.push_back(from + (to - from) * k / n);
      };
      path.push_back(-0.02 * Rmin);
      walk(-0.02 * Rmin, 0.3 * Rmin);
      walk(0.3 * Rmin, 0.1 * Rmin);
      walk(0.1 * Rmin, 0.4 * Rmin);
      walk(0.4 * Rmin, -0.02 * Rmin);
      ContactStepper<M> s(model, c.R0, c.R1, 0, 1);
      std::vector<double> F;
      double worst_balance = 0, Fpeak = 0;
      int yielded = 0;
      for (double d : path) {
        F.push_back(s.step(d));
        auto side = [&](int k, int what) {
          return s.evaluate(MdrOutputField{MdrOutputField::Field(what), k});  // 0 force, 1 overlap, 2 yielded
        };
        const double F0 = side(0, 0), F1 = side(1, 0);
        const double sc = lam0 * std::fabs(F0) + lam1 * std::fabs(F1);
        if (sc > 0) worst_balance = std::max(worst_balance, std::fabs(lam0 * F0 - lam1 * F1) / sc);
        if (F.back() != 0.0) {
          CHECK(side(0, 1) + side(1, 1) == Approx(s.overlap()).epsilon(same).margin(1e-6 * h));
          Fpeak = std::max(Fpeak, std::fabs(F.back()));
          CHECK(F.back() ==
                Approx(0.5 * (F0 + F1)).epsilon(same).margin(same * 1e-2 * Fpeak));  // margin: near separation
        }
        yielded = std::max(yielded, static_cast<int>(side(0, 2)));
      }
      CHECK(worst_balance < tol);
      CHECK(yielded >= 1);
      const CycleWork w = cycle_work(path, F);
      INFO("in " << w.in << ", out " << w.out << ", relative " << (w.out - w.in) / w.in);
      REQUIRE(w.in > 0);
      CHECK(w.out < w.in);  // a yielded pair dissipates
      CHECK(F.back() == 0.0);
    }
}

TEMPLATE_LIST_TEST_CASE("MDR pair_split geometric: the authors' radical plane while loading, the mean of the sides",
                        "[mdr][pair]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity>, D>;
  const double tol = sizeof(T) >= 8 ? 1e-12 : 1e-5;
  const Material a = mdr_material(1e8, 0.3, 2e6);
  MdrOptions geo;
  geo.pair_split = MdrPairSplit::geometric;
  for (const double R1 : {1e-3, 3e-3}) {
    CAPTURE(R1);
    const double R0 = 1e-3;
    ContactStepper<M> g(M::create({a}, geo), R0, R1, 0, 0), b(M::create({a}), R0, R1, 0, 0);
    double worst_split_gap = 0;
    for (int k = 1; k <= 600; ++k) {  // monotonic loading to 0.3 R0: delta = dmax, plastic
      const double d = 0.3 * R0 * k / 600;
      const double Fg = g.step(d), Fb = b.step(d);
      // outputs of the stored state: 0 side 0's overlap, 1 and 2 the sides' forces
      auto out = [](ContactStepper<M>& s, int what) {
        return s.evaluate(what == 0 ? MdrOutputField{MdrOutputField::side_overlap, 0}
                                    : MdrOutputField{MdrOutputField::side_force, what - 1});
      };
      // the side of particle 0 sits at the radical plane's cap height (mdr_side0_height)
      const double h0 = double(mdr_side0_height(T(g.overlap()), T(R0), T(R1)));
      const double dg0 = out(g, 0), db0 = out(b, 0);
      CHECK(dg0 == Approx(h0).epsilon(tol).margin(1e-9 * d));
      CHECK(Fg == Approx(0.5 * (out(g, 1) + out(g, 2))).epsilon(tol * 10));
      worst_split_gap = std::max(worst_split_gap, std::fabs(dg0 - db0) / d);
      if (R1 == R0) CHECK(Fg == Approx(Fb).epsilon(tol * 10));  // equal spheres: both splits are delta/2
    }
    // unequal yielded spheres: the default split (equal_pair) moves the flat off the radical plane
    if (R1 != R0)
      CHECK(worst_split_gap > 1e-3);
    else
      CHECK(worst_split_gap < tol);
  }
}
