// Evaluation of MDR pair splits for issue 18 item 1 (docs/mdr-pair-split-evaluation.md): not a CI
// test (its cases are hidden, "[.eval]", and the executable is not registered with ctest). For
// each MdrPairSplit it prints
//   (a) the worst deviation from Hertz (E*, R*) of elastic pairs, radius ratios 1-100, modulus
//       ratios 1-100 (both ways), delta/R* <= 0.01;
//   (b) the force of same-material plastic pairs over the equal pair with the same R* (radius
//       2 R*): the table (ratios 2 and 5, delta/R* 0.03 / 0.06 / 0.1, E/Y 200) and the worst
//       deviation over radius ratios 1-10, E/Y 20-1000, to delta/R* = 0.1 and 0.3;
//   (c) closed random cycles that create energy (the CI fuzz generator, tests/stability);
//   and, for the written analysis: the sides' overlaps, areas and cap volumes (what radius growth
//   sees), the interface's force imbalance of mixed-material plastic pairs, JKR pull-off.
// Run: OMP_NUM_THREADS=1 eval_mdr_split "[.eval]"   (EVAL_FUZZ_PATHS: paths per split, default 5000)
#include "../stability/fuzz_paths.hpp"
#include "contact_stepper.hpp"
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

using namespace epac;
using namespace epac::test;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
using D = DeviceOf<Kokkos::Serial>;
using T = double;
using M = Mdr<T, Effects<kPlasticity>, D>;
using MA = Mdr<T, Effects<kPlasticity | kAdhesion>, D>;

const MdrPairSplit kSplits[] = {MdrPairSplit::balanced, MdrPairSplit::geometric, MdrPairSplit::equal_pair,
                                MdrPairSplit::equal_pair_balanced};
const char* split_name(MdrPairSplit s);
// EVAL_SPLITS=<text>: the fuzz runs only the splits whose name contains it (e.g. "equal")
bool fuzz_this(MdrPairSplit s) {
  const char* only = std::getenv("EVAL_SPLITS");
  return !only || std::string(split_name(s)).find(only) != std::string::npos;
}
const char* split_name(MdrPairSplit s) {
  switch (s) {
    case MdrPairSplit::balanced:
      return "balanced";
    case MdrPairSplit::geometric:
      return "geometric";
    case MdrPairSplit::equal_pair:
      return "equal_pair";
    default:
      return "equal_pair_balanced";
  }
}
MdrOptions opts(MdrPairSplit s) {
  MdrOptions o;
  o.pair_split = s;
  return o;
}

// side quantities of the stored contact: 0 force, 1 overlap, 2 area, 3 yielded count
struct SideOut {
  int what, side;
  template <class Mo, class G, class Row>
  KOKKOS_INLINE_FUNCTION typename Mo::scalar_type operator()(const Mo& m, const G& g, const Row& row) const {
    const auto o = m.outputs(g, row);
    return what == 0   ? o.side_force[side]
           : what == 1 ? o.side_overlap[side]
           : what == 2 ? o.side_area[side]
                       : o.yielded;
  }
};

double E_eff(double E, double nu) { return E / (1 - nu * nu); }

// monotonic loading of a pair to delta/R* = xmax in n steps: forces at each step
template <class Model>
std::vector<double> load_pair(const Model& model, double R0, double R1, int m0, int m1, double xmax, int n) {
  ContactStepper<Model> s(model, R0, R1, m0, m1);
  const double Rs = R0 * R1 / (R0 + R1);
  std::vector<double> F;
  for (int k = 1; k <= n; ++k) F.push_back(s.step(xmax * Rs * k / n));
  return F;
}
}  // namespace

TEST_CASE("eval (a): elastic pairs against Hertz with E* and R*", "[.eval]") {
  const double E = 1e8, R0 = 1e-3;
  const double ratios[] = {1, 2, 5, 10, 30, 100};
  const double mods[] = {0.01, 0.1, 1.0 / 3, 1, 3, 10, 100};  // E_1/E_0
  std::printf(
      "\n(a) elastic pairs (nu 0.3 / 0.2), delta/R* <= 0.01 (60 steps): worst |F/F_Hertz(E*, R*) - 1| over "
      "R_1/R_0 = 1, 2, 5, 10, 30, 100, per E_1/E_0\n%-20s",
      "split");
  for (double m : mods) std::printf(" %9.3g", m);
  std::printf("\n");
  for (MdrPairSplit sp : kSplits) {
    std::printf("%-20s", split_name(sp));
    for (double m : mods) {
      double worst = 0;
      for (double r : ratios) {
        const Material a = mdr_material(E, 0.3, kInf), b = mdr_material(E * m, 0.2, kInf);
        const M model = M::create({a, b}, opts(sp));
        const double R1 = r * R0, Rs = R0 * R1 / (R0 + R1);
        const double Es = 1.0 / (1.0 / E_eff(E, 0.3) + 1.0 / E_eff(E * m, 0.2));
        const int n = 60;
        const std::vector<double> F = load_pair(model, R0, R1, 0, 1, 0.01, n);
        for (int k = 0; k < n; ++k) {
          const double x = 0.01 * (k + 1) / n, d = x * Rs;
          const double Fh = 4.0 / 3.0 * Es * std::sqrt(Rs) * std::pow(d, 1.5);
          worst = std::max(worst, std::fabs(F[k] / Fh - 1));
        }
      }
      std::printf(" %9.2e", worst);
    }
    std::printf("\n");
  }
  // one material (the check): every radius ratio, nu 0.3 both
  std::printf("one material (nu 0.3), worst over R_1/R_0 = 1-100:\n");
  for (MdrPairSplit sp : kSplits) {
    double worst = 0;
    for (double r : ratios) {
      const M model = M::create({mdr_material(E, 0.3, kInf)}, opts(sp));
      const double R1 = r * R0, Rs = R0 * R1 / (R0 + R1), Es = 0.5 * E_eff(E, 0.3);
      const std::vector<double> F = load_pair(model, R0, R1, 0, 0, 0.01, 60);
      for (int k = 0; k < 60; ++k) {
        const double d = 0.01 * (k + 1) / 60 * Rs;
        worst = std::max(worst, std::fabs(F[k] / (4.0 / 3.0 * Es * std::sqrt(Rs) * std::pow(d, 1.5)) - 1));
      }
    }
    std::printf("%-20s %9.2e\n", split_name(sp), worst);
  }
}

TEST_CASE("eval (b): same-material plastic pairs against the equal pair with the same R*", "[.eval]") {
  const double E = 1e8, nu = 0.3, R0 = 1e-3;
  std::printf("\n(b) same material, nu 0.3: F(R_0, R_1) / F(2R*, 2R*) at the same delta\n");
  std::printf("issue's table, E/Y 200:\n%-20s %-24s %-24s\n", "split", "ratio 2: 0.03/0.06/0.1",
              "ratio 5: 0.03/0.06/0.1");
  for (MdrPairSplit sp : kSplits) {
    const M model = M::create({mdr_material(E, nu, E / 200)}, opts(sp));
    std::printf("%-20s", split_name(sp));
    for (double r : {2.0, 5.0}) {
      const double R1 = r * R0, Rs = R0 * R1 / (R0 + R1);
      const int n = 1000;
      const std::vector<double> F = load_pair(model, R0, R1, 0, 0, 0.1, n);
      const std::vector<double> Fe = load_pair(model, 2 * Rs, 2 * Rs, 0, 0, 0.1, n);
      std::printf(" %.3f / %.3f / %.3f    ", F[299] / Fe[299], F[599] / Fe[599], F[999] / Fe[999]);
    }
    std::printf("\n");
  }
  std::printf("worst |F/F_equal - 1| over radius ratios 1,1.5,2,3,5,10 x E/Y 20,50,200,1000 (loading, 1000 steps):\n");
  std::printf("%-20s %-34s %-34s\n", "split", "to delta/R* 0.1 (ratio, E/Y, x)", "to delta/R* 0.3 (ratio, E/Y, x)");
  for (MdrPairSplit sp : kSplits) {
    std::printf("%-20s", split_name(sp));
    for (double xmax : {0.1, 0.3}) {
      double worst = 0, wr = 0, we = 0, wx = 0;
      for (double r : {1.0, 1.5, 2.0, 3.0, 5.0, 10.0})
        for (double EY : {20.0, 50.0, 200.0, 1000.0}) {
          const M model = M::create({mdr_material(E, nu, E / EY)}, opts(sp));
          const double R1 = r * R0, Rs = R0 * R1 / (R0 + R1);
          const int n = 1000;
          const std::vector<double> F = load_pair(model, R0, R1, 0, 0, xmax, n);
          const std::vector<double> Fe = load_pair(model, 2 * Rs, 2 * Rs, 0, 0, xmax, n);
          for (int k = 0; k < n; ++k) {
            const double dev = std::fabs(F[k] / Fe[k] - 1);
            if (dev > worst) {
              worst = dev;
              wr = r;
              we = EY;
              wx = xmax * (k + 1) / n;
            }
          }
        }
      std::printf(" %.3e (%g, %g, %.3f)         ", worst, wr, we, wx);
    }
    std::printf("\n");
  }
}

namespace {
template <class T_>
struct MakeMdrSplit {
  using M = Mdr<T_, Effects<kAllButGrowth>>;
  static constexpr const char* name = "mdr";
  static MdrPairSplit split;
  static M make(const std::vector<Material>& m) { return M::create(m, opts(split)); }
};
template <class T_>
MdrPairSplit MakeMdrSplit<T_>::split = MdrPairSplit::balanced;
template <class T_>
struct MakeMdrGrowthSplit {
  using M = Mdr<T_, Effects<kAllEffects>>;
  static constexpr const char* name = "mdr+growth";
  static MdrPairSplit split;
  static M make(const std::vector<Material>& m) { return M::create(m, opts(split)); }
};
template <class T_>
MdrPairSplit MakeMdrGrowthSplit<T_>::split = MdrPairSplit::balanced;
}  // namespace

TEST_CASE("eval (c): random closed cycles that create energy (the CI fuzz generator)", "[.eval][.fuzz]") {
  const char* env = std::getenv("EVAL_FUZZ_PATHS");
  const long n = env ? std::atol(env) : 5000;
  std::printf("\n(c) %ld fuzz paths per split (a wall and a pair each; the seed of the CI's mdr section)\n", n);
  for (MdrPairSplit sp : kSplits) {
    if (!fuzz_this(sp)) continue;
    MakeMdrSplit<double>::split = sp;
    MakeMdrGrowthSplit<double>::split = sp;
    const FuzzCounts c = fuzz_paths<MakeMdrSplit<double>, double>(n, 4, 512, 1);
    std::printf(
        "%-20s mdr        NaN %ld Inf %ld energy created %ld of %ld closed cycles (worst (out-in)/in %.3g); "
        "plastic pairs %ld of %ld (worst %.3g)\n",
        split_name(sp), c.nan, c.inf, c.energy_created, c.energy_checked, c.worst_energy, c.plastic_pair_energy_created,
        c.plastic_pair_checked, c.worst_plastic_pair);
    const FuzzCounts g = fuzz_paths<MakeMdrGrowthSplit<double>, double>(n, 5, 512, 1);
    std::printf(
        "%-20s mdr+growth NaN %ld Inf %ld energy created %ld of %ld closed cycles (worst (out-in)/in %.3g); "
        "plastic pairs %ld of %ld (worst %.3g)\n",
        split_name(sp), g.nan, g.inf, g.energy_created, g.energy_checked, g.worst_energy, g.plastic_pair_energy_created,
        g.plastic_pair_checked, g.worst_plastic_pair);
    std::fflush(stdout);
  }
}

TEST_CASE("eval (c-float): random closed cycles that create energy", "[.eval][.fuzz]") {
  const char* env = std::getenv("EVAL_FUZZ_PATHS");
  const long n = env ? std::atol(env) : 5000;
  std::printf("\n(c) float: %ld fuzz paths per split\n", n);
  for (MdrPairSplit sp : kSplits) {
    if (!fuzz_this(sp)) continue;
    MakeMdrSplit<float>::split = sp;
    MakeMdrGrowthSplit<float>::split = sp;
    const FuzzCounts c = fuzz_paths<MakeMdrSplit<float>, float>(n, 8, 512, 1);
    const FuzzCounts g = fuzz_paths<MakeMdrGrowthSplit<float>, float>(n, 10, 512, 1);
    std::printf(
        "%-20s mdr NaN %ld Inf %ld created %ld of %ld (worst %.3g), plastic pairs %ld of %ld; mdr+growth NaN %ld "
        "Inf %ld created %ld of %ld (worst %.3g)\n",
        split_name(sp), c.nan, c.inf, c.energy_created, c.energy_checked, c.worst_energy, c.plastic_pair_energy_created,
        c.plastic_pair_checked, g.nan, g.inf, g.energy_created, g.energy_checked, g.worst_energy);
    std::fflush(stdout);
  }
}

TEST_CASE("eval (c'): targeted closed cycles of yielded unequal and mixed pairs", "[.eval]") {
  // load - unload - reload - unload to a gap on one grid (each segment crossed as often up as down)
  std::printf("\n(c') targeted cycles: radius ratios 1-30, one material and mixed (E, Y), worst (out - in)/in\n");
  struct Case {
    double r, E1, Y0, Y1;
  };
  const double E = 1e8, R0 = 1e-3;
  const Case cases[] = {{3, 1, 200, 200},  {5, 1, 20, 20},    {10, 1, 1000, 1000},  {3, 1, 200, kInf},
                        {5, 30, 200, 50},  {30, 3, 50, 500},  {0.2, 0.05, 100, 20}, {1, 1, 200, kInf},
                        {1, 10, 50, 1000}, {2, 0.3, kInf, 30}};
  for (MdrPairSplit sp : kSplits) {
    double worst = -1;
    for (const Case& c : cases) {
      auto Y = [](double E_, double EY) { return std::isinf(EY) ? kInf : E_ / EY; };
      const M model =
          M::create({mdr_material(E, 0.3, Y(E, c.Y0)), mdr_material(E * c.E1, 0.25, Y(E * c.E1, c.Y1))}, opts(sp));
      const double R1 = c.r * R0, Rm = std::min(R0, R1);
      const double h = 5e-4 * Rm;
      std::vector<double> path{-0.02 * Rm};
      auto walk = [&](double from, double to) {
        const int k = static_cast<int>(std::lround(std::fabs(to - from) / h));
        for (int j = 1; j <= k; ++j) path.push_back(from + (to - from) * j / k);
      };
      walk(-0.02 * Rm, 0.3 * Rm);
      walk(0.3 * Rm, 0.1 * Rm);
      walk(0.1 * Rm, 0.4 * Rm);
      walk(0.4 * Rm, -0.02 * Rm);
      ContactStepper<M> s(model, R0, R1, 0, 1);
      double in = 0, out = 0, Fp = 0;
      for (std::size_t k = 0; k < path.size(); ++k) {
        const double F = s.step(path[k]);
        if (k > 0) {
          const double w = 0.5 * (F + Fp) * (path[k] - path[k - 1]);
          (w > 0 ? in : out) += std::fabs(w);
        }
        Fp = F;
      }
      worst = std::max(worst, (out - in) / in);
    }
    std::printf("%-20s worst (out - in)/in %.3e (negative: every cycle dissipates)\n", split_name(sp), worst);
  }
}

TEST_CASE("eval: sides, areas and cap volumes of plastic pairs (what growth and Part II see)", "[.eval]") {
  // one material, E/Y 200, radius ratio 5, loaded to delta/R* = 0.05: each side's overlap d_s,
  // area (42), the cap volume pi d_s^2 (3 R_s - d_s)/3 that MDR (37)/(C.1) removes from particle s
  // with its own radius, against the lens volume shared half and half (one material: both
  // surfaces take the same displacement) and the lens rim area 2 pi R* delta (to first order)
  const double E = 1e8, R0 = 1e-3, r = 5, R1 = r * R0, Rs = R0 * R1 / (R0 + R1), x = 0.05, delta = x * Rs;
  std::printf(
      "\nsides of a one-material pair, E/Y 200, R_1/R_0 = 5, delta/R* = 0.05 (lens rim area 2 pi R* delta = "
      "%.4e, lens volume ~pi R* delta^2 = %.4e)\n",
      2 * M_PI * Rs * delta, M_PI * Rs * delta * delta);
  std::printf("%-20s %10s %10s %11s %11s %12s %12s %10s %10s\n", "split", "d_0/delta", "d_1/delta", "area_0/rim",
              "area_1/rim", "cap_0/lens", "cap_1/lens", "F_0/F", "F_1/F");
  for (MdrPairSplit sp : kSplits) {
    const M model = M::create({mdr_material(E, 0.3, E / 200)}, opts(sp));
    ContactStepper<M> s(model, R0, R1, 0, 0);
    double F = 0;
    for (int k = 1; k <= 500; ++k) F = s.step(delta * k / 500);
    const double d0 = s.evaluate(SideOut{1, 0}), d1 = s.evaluate(SideOut{1, 1});
    const double A0 = s.evaluate(SideOut{2, 0}), A1 = s.evaluate(SideOut{2, 1});
    const double F0 = s.evaluate(SideOut{0, 0}), F1 = s.evaluate(SideOut{0, 1});
    auto cap = [](double d, double R) { return M_PI * d * d * (3 * R - d) / 3; };
    const double lens =
        cap(double(mdr_side0_height(delta, R0, R1)), R0) + cap(delta - double(mdr_side0_height(delta, R0, R1)), R1);
    std::printf("%-20s %10.4f %10.4f %11.4f %11.4f %12.4f %12.4f %10.4f %10.4f\n", split_name(sp), d0 / delta,
                d1 / delta, A0 / (2 * M_PI * Rs * delta), A1 / (2 * M_PI * Rs * delta), cap(d0, R0) / lens,
                cap(d1, R1) / lens, F0 / F, F1 / F);
  }
}

TEST_CASE("eval: mixed-material plastic pairs, the flat's equilibrium", "[.eval]") {
  // equal radii, one modulus, side 0 plastic (E/Y 200), side 1 elastic or harder: the sides'
  // forces on the flat, and the pair force at delta/R* = 0.1 against the plastic sphere pressed by
  // a rigid sphere of the same radius (the wall-like limit is not a reference; printed for scale)
  const double E = 1e8, R0 = 1e-3;
  std::printf(
      "\nmixed plastic pairs at delta/R* = 0.1, equal radii: F_0/F_1 (side forces on the flat), F / F(one "
      "material, E/Y 200)\n");
  std::printf("%-20s %22s %22s %22s\n", "split", "Y_1 = inf, E_1 = E_0", "E_1/Y_1 = 50", "E_1 = 10 E_0, elastic");
  for (MdrPairSplit sp : kSplits) {
    std::printf("%-20s", split_name(sp));
    const M ref = M::create({mdr_material(E, 0.3, E / 200)}, opts(sp));
    const double Fref = load_pair(ref, R0, R0, 0, 0, 0.1, 500).back();
    const Material other[] = {mdr_material(E, 0.3, kInf), mdr_material(E, 0.3, E / 50),
                              mdr_material(10 * E, 0.3, kInf)};
    for (const Material& b : other) {
      const M model = M::create({mdr_material(E, 0.3, E / 200), b}, opts(sp));
      ContactStepper<M> s(model, R0, R0, 0, 1);
      double F = 0;
      for (int k = 1; k <= 500; ++k) F = s.step(0.1 * 0.5 * R0 * k / 500);
      const double F0 = s.evaluate(SideOut{0, 0}), F1 = s.evaluate(SideOut{0, 1});
      std::printf("  %7.3f / %6.3f (%d)", F0 / F1, F / Fref, int(s.evaluate(SideOut{3, 0})));
    }
    std::printf("\n");
  }
}

TEST_CASE("eval: adhesive pairs, pull-off against JKR and against the equal pair", "[.eval]") {
  const double E = 1e8, R0 = 1e-3, gamma = 0.5;
  std::printf(
      "\nadhesion (series share of Delta gamma): pull-off / (1.5 pi Delta gamma R*) elastic; plastic one "
      "material E/Y 200 to delta/R* 0.05: pull-off / equal pair's\n");
  std::printf("%-20s %14s %14s %14s %14s %14s\n", "split", "el. r1 E1/E0=1", "el. r5 E1/E0=1", "el. r5 E1/E0=3",
              "el. r20 E1/E0=.1", "pl. r5 / equal");
  for (MdrPairSplit sp : kSplits) {
    std::printf("%-20s", split_name(sp));
    auto pulloff = [&](const MA& model, double R0_, double R1_, double load) {
      ContactStepper<MA> s(model, R0_, R1_, 0, 1);
      double tension = 0;
      for (int k = 1; k <= 400; ++k) s.step(load * k / 400);
      for (int k = 1; k <= 4000; ++k) tension = std::min(tension, s.step(load * (1 - 1.5 * k / 4000.0)));
      return -tension;
    };
    const double cases[4][2] = {{1, 1}, {5, 1}, {5, 3}, {20, 0.1}};
    for (const auto& c : cases) {
      const MA model =
          MA::create({mdr_material(E, 0.3, kInf, gamma), mdr_material(E * c[1], 0.3, kInf, gamma)}, opts(sp));
      const double R1 = c[0] * R0, Rs = R0 * R1 / (R0 + R1);
      const double Es = 1.0 / (1.0 / E_eff(E, 0.3) + 1.0 / E_eff(E * c[1], 0.3));
      const double a0 = std::cbrt(9 * M_PI * gamma * Rs * Rs / (2 * Es));  // JKR contact radius at zero load... scale
      const double load = 3 * a0 * a0 / Rs;
      std::printf(" %14.4f", pulloff(model, R0, R1, load) / (1.5 * M_PI * gamma * Rs));
    }
    const MA pm = MA::create({mdr_material(E, 0.3, E / 200, gamma), mdr_material(E, 0.3, E / 200, gamma)}, opts(sp));
    const double R1 = 5 * R0, Rs = R0 * R1 / (R0 + R1);
    std::printf(" %14.4f\n", pulloff(pm, R0, R1, 0.05 * Rs) / pulloff(pm, 2 * Rs, 2 * Rs, 0.05 * Rs));
  }
}

TEST_CASE("eval: radius growth of one-material pairs (volume each particle gains)", "[.eval]") {
  // E/Y 200, nu 0.3, radius ratio 5 and 2, delta_o/R* to 0.3 in 2000 steps (the
  // centre distance from the initial radii, growth adding to the overlap as in a packing): the
  // volume 4/3 pi (R^3 - R_o^3) each particle gained, over the lens volume at the largest delta_o
  // (two radical-plane caps of the initial radii); reference: each particle of the equal pair 2R*
  using MG = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  const double E = 1e8, R0 = 1e-3;
  auto cap = [](double d, double R) { return M_PI * d * d * (3 * R - d) / 3; };
  std::printf("\nradius growth, one material E/Y 200, delta_o/R* to 0.3: volume gained / lens volume\n");
  std::printf("%-20s %24s %24s\n", "split", "ratio 2: small / large", "ratio 5: small / large");
  for (int ref = 0; ref < 2; ++ref)
    for (MdrPairSplit sp : kSplits) {
      if (ref && sp != MdrPairSplit::balanced) continue;
      std::printf("%-20s", ref ? "equal pair 2R*" : split_name(sp));
      for (double r : {2.0, 5.0}) {
        const double R1 = r * R0, Rs = R0 * R1 / (R0 + R1), dmax = 0.3 * Rs;
        const double a = ref ? 2 * Rs : R0, b = ref ? 2 * Rs : R1;
        const MG model = MG::create({mdr_material(E, 0.3, E / 200)}, opts(sp));
        std::vector<double> path;
        append_ramp(path, 0.0, dmax, 2000);
        const PairTrace t = run_pair_path<MG, D>(model, a, b, 0, path);
        const double h0 = double(mdr_side0_height(dmax, a, b));
        const double lens = cap(h0, a) + cap(dmax - h0, b);
        const double V0 = 4.0 / 3 * M_PI * (std::pow(t.R0.back(), 3) - a * a * a);
        const double V1 = 4.0 / 3 * M_PI * (std::pow(t.R1.back(), 3) - b * b * b);
        std::printf("      %8.4f / %8.4f", V0 / lens, V1 / lens);
      }
      std::printf("\n");
    }
}
