// MDR particle pairs: the rigid flat at the contact plane, through the generic pair kernel.
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace epac;
using namespace epac::test;

namespace {

// Two particles on the x axis (gids gid0, gid1, radii R0, R1), pressed through a sequence of
// total overlaps; returns the normal force on the first particle along n (law output) and checks
// the two particles' forces are equal and opposite.
template <class Model, class D, class T = typename Model::scalar_type>
std::vector<double> run_pair(const Model& model, double R0, double R1, int gid0, int gid1, bool list_01,
                             const std::vector<double>& overlaps, double* max_imbalance) {
  Particles<T, D> p(2);
  auto r = Kokkos::create_mirror_view(p.radius);
  auto m = Kokkos::create_mirror_view(p.mass);
  auto g = Kokkos::create_mirror_view(p.gid);
  r(0) = T(R0);
  r(1) = T(R1);
  m(0) = T(1);
  m(1) = T(1);
  g(0) = gid0;
  g(1) = gid1;
  Kokkos::deep_copy(p.radius, r);
  Kokkos::deep_copy(p.radius0, r);
  Kokkos::deep_copy(p.mass, m);
  Kokkos::deep_copy(p.gid, g);
  ContactList<D> c(1);
  {
    auto f = Kokkos::create_mirror_view(c.first);
    auto s = Kokkos::create_mirror_view(c.second);
    f(0) = list_01 ? 0 : 1;
    s(0) = list_01 ? 1 : 0;
    Kokkos::deep_copy(c.first, f);
    Kokkos::deep_copy(c.second, s);
  }
  ContactHistory<T, D> h(1, Model::history_size);
  ContactOutputs<T, D> out;
  out.normal_force = Kokkos::View<T*, D>("fn", 1);
  auto x = Kokkos::create_mirror_view(p.x);
  std::vector<double> F;
  *max_imbalance = 0.0;
  for (double d : overlaps) {
    x(0, 0) = T(0);
    x(1, 0) = T(R0 + R1 - d);
    Kokkos::deep_copy(p.x, x);
    zero_forces(p);
    compute_pair_forces(model, p, c, h, T(0), out);
    auto fn = to_host(out.normal_force);
    auto f = to_host(p.force);
    F.push_back(fn(0));
    const double scale = std::max(std::fabs(double(f(0, 0))), 1e-300);
    *max_imbalance = std::max(*max_imbalance, std::fabs(double(f(0, 0)) + double(f(1, 0))) / scale);
    // the force on particle 0 points away from particle 1 (-x) when compressive, whatever the
    // list order
    if (fn(0) > 0) CHECK(f(0, 0) < 0);
  }
  return F;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("MDR pair: equal spheres at d per sphere = sphere on a flat at d; equal and opposite",
                        "[mdr][pair]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kAdhesion>, D>;
  const double E = 1.0, R = 1.0;
  const double tol = sizeof(T) >= 8 ? 1e-12 : 2e-5;
  for (double EY : {0.0, 25.0}) {
    const double Y = EY == 0.0 ? std::numeric_limits<double>::infinity() : E / EY;
    const M model = M::create({mdr_material(E, kNu, Y), rigid_wall_material()});
    const auto c = side_constants<T>(E, kNu, Y);
    std::vector<double> per_sphere;
    append_ramp(per_sphere, 0.0, 0.2 * R, 100);
    append_ramp(per_sphere, 0.2 * R, 0.0, 200);
    std::vector<double> total;
    for (double d : per_sphere) total.push_back(2 * d);
    double imbalance = 0;
    const std::vector<double> Fp = run_pair<M, D>(model, R, R, 0, 1, true, total, &imbalance);
    const SideTrace t = run_side_path<D, T, true, false>(c, 0.0, 1.0, R, per_sphere);
    double peak = 0;
    for (double f : t.F) peak = std::max(peak, f);
    INFO("E/Y = " << EY);
    for (size_t k = 0; k < Fp.size(); ++k) CHECK(std::fabs(Fp[k] - t.F[k]) < tol * peak + 1e-300);
    CHECK(imbalance < 1e-6);
    if (EY > 0) CHECK(t.yielded.back() == 1);  // the plastic range is covered too
  }
}

TEMPLATE_LIST_TEST_CASE("MDR pair: sides follow the global ids, not the list order", "[mdr][pair]", Backends) {
  using D = TestType;
  using T = double;
  using M = Mdr<T, Effects<kPlasticity>, D>;
  const M model = M::create({mdr_material(1.0, kNu, 1.0 / 50.0), rigid_wall_material()});
  std::vector<double> total;
  append_ramp(total, 0.0, 0.5, 100);
  append_ramp(total, 0.5, 0.0, 100);
  double imb1 = 0, imb2 = 0, imb3 = 0;
  // unequal radii 1 and 2; gids (5, 9); list (0,1) vs (1,0)
  const auto Fa = run_pair<M, D>(model, 1.0, 2.0, 5, 9, true, total, &imb1);
  const auto Fb = run_pair<M, D>(model, 1.0, 2.0, 5, 9, false, total, &imb2);
  // swapping the gids swaps which particle is side 0: same physics
  const auto Fc = run_pair<M, D>(model, 1.0, 2.0, 9, 5, true, total, &imb3);
  for (size_t k = 0; k < Fa.size(); ++k) {
    CHECK(Fb[k] == Approx(Fa[k]).margin(1e-14));
    CHECK(Fc[k] == Approx(Fa[k]).margin(1e-14));
  }
  CHECK(imb1 < 1e-12);
  CHECK(imb2 < 1e-12);
}

TEMPLATE_LIST_TEST_CASE("MDR pair split: radical plane, 0.75 R cap, residuals reached together, guards",
                        "[mdr][pair][guard]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  Kokkos::View<double**, Kokkos::LayoutRight, D> o("o", 8, 2);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        const T R0 = 1, R1 = 3;
        // at dmax: radical-plane caps; the smaller sphere takes the larger one
        MdrSideOverlaps<T> s = mdr_split_overlap(T(0.2), T(0.2), R0, R1, T(0), T(0));
        o(0, 0) = s.d0;
        o(0, 1) = s.d1;
        // cap: dmax = 1.5 would give the small sphere a cap above 0.75 R0
        s = mdr_split_overlap(T(1.5), T(1.5), R0, R1, T(0), T(0));
        o(1, 0) = s.d0;
        o(1, 1) = s.d1;
        // unloading: at delta = dp0 + dp1 both sides sit at their residuals
        s = mdr_split_overlap(T(0.15), T(0.3), R0, R1, T(0.1), T(0.05));
        o(2, 0) = s.d0;
        o(2, 1) = s.d1;
        // halfway between dmax and the residual sum
        s = mdr_split_overlap(T(0.225), T(0.3), R0, R1, T(0.1), T(0.05));
        o(3, 0) = s.d0;
        o(3, 1) = s.d1;
        // guard: coincident centres (dmax >= R0 + R1)
        s = mdr_split_overlap(T(4.5), T(4.5), R0, R1, T(0), T(0));
        o(4, 0) = s.d0;
        o(4, 1) = s.d1;
        // guard: residuals summing to dmax (no elastic recovery)
        s = mdr_split_overlap(T(0.25), T(0.3), R0, R1, T(0.2), T(0.1));
        o(5, 0) = s.d0;
        o(5, 1) = s.d1;
        // never pressed (dmax = 0), apart: radical plane at the current overlap
        s = mdr_split_overlap(T(-0.01), T(0), R0, R1, T(0), T(0));
        o(6, 0) = s.d0;
        o(6, 1) = s.d1;
      });
  auto h = to_host(o);
  const double tol = sizeof(T) >= 8 ? 1e-12 : 1e-5;
  // radical plane: h0 = d (2 R1 - d) / (2 (R0 + R1 - d))
  CHECK(h(0, 0) == Approx(0.2 * (6 - 0.2) / (2 * (4 - 0.2))).epsilon(tol));
  CHECK(h(0, 0) + h(0, 1) == Approx(0.2).epsilon(tol));
  CHECK(h(0, 0) > h(0, 1));
  CHECK(h(1, 0) == Approx(0.75).epsilon(tol));
  CHECK(h(1, 1) == Approx(0.75).epsilon(tol));
  CHECK(h(2, 0) == Approx(0.1).epsilon(tol));
  CHECK(h(2, 1) == Approx(0.05).epsilon(tol));
  // halfway (x = delta - (e0 + e1) = X / 2): e0 + h0(x) + (x / X) (E0 - h0(X)), h0(.) the radical
  // height (mdr_pair_split.hpp; the old linear split gave (h0 + 0.1) / 2 here)
  auto hc = [](double d) { return d * (6 - d) / (2 * (4 - d)); };
  const double h0 = hc(0.3);
  CHECK(h(3, 0) == Approx(0.1 + hc(0.075) + 0.5 * (h0 - 0.1 - hc(0.15))).epsilon(tol));
  CHECK(h(3, 0) + h(3, 1) == Approx(0.225).epsilon(tol));
  // residuals summing to more than dmax (side 1's clipped to its height h1 = dmax - h0): delta
  // lies below the clipped sum, so both sides sit below their residuals by at most the distance
  const double e1 = 0.3 - h0, below = 0.2 + e1 - 0.25;
  CHECK(h(5, 0) <= 0.2 + tol);
  CHECK(h(5, 1) <= e1 + tol);
  CHECK(h(5, 0) >= 0.2 - below - tol);
  CHECK(h(5, 1) >= e1 - below - tol);
  CHECK(h(5, 0) + h(5, 1) == Approx(0.25).epsilon(tol));
  for (int r = 0; r < 7; ++r) {
    CHECK(std::isfinite(h(r, 0)));
    CHECK(std::isfinite(h(r, 1)));
  }
  CHECK(h(4, 0) == Approx(0.75).epsilon(tol));
  CHECK(h(4, 0) + h(4, 1) == Approx(4.5).epsilon(tol));
  CHECK(h(6, 0) < 0.0);
  CHECK(h(6, 0) + h(6, 1) == Approx(-0.01).epsilon(tol));
}

TEMPLATE_LIST_TEST_CASE("MDR pair, adhesive and elastic: JKR between the two spheres; tension below zero overlap",
                        "[mdr][pair][adhesion]", Backends) {
  using D = TestType;
  using T = double;
  using M = Mdr<T, Effects<kPlasticity | kAdhesion>, D>;
  const double E = 1.0, R = 1.0, Eeff = E / (1 - kNu * kNu);
  const double gamma = Eeff * R / 2.2e4;
  const M model =
      M::create({mdr_material(E, kNu, std::numeric_limits<double>::infinity(), gamma), rigid_wall_material()});
  std::vector<double> total;
  append_ramp(total, 0.0, 8e-3 * R, 200);
  append_ramp(total, 8e-3 * R, -0.01 * R, 9000);
  double imbalance = 0;
  const std::vector<double> F = run_pair<M, D>(model, R, R, 0, 1, true, total, &imbalance);
  const Jkr jkr{Eeff / 2, R / 2, gamma};  // two spheres: E* = E_eff/2, R* = R/2
  double max_tension = 0;
  bool tension_below_zero = false;
  int sep = -1;
  for (size_t k = 200; k < F.size(); ++k) {
    max_tension = std::max(max_tension, -F[k]);
    if (total[k] < 0 && F[k] < 0) tension_below_zero = true;
    if (sep < 0 && k > 200 && F[k] == 0.0 && F[k - 1] < 0.0) sep = static_cast<int>(k);
  }
  CHECK(max_tension == Approx(jkr.pull_off()).epsilon(0.01));
  CHECK(tension_below_zero);
  REQUIRE(sep > 0);
  for (size_t k = sep; k < F.size(); ++k) CHECK(F[k] == 0.0);  // separated, history reset
  // on the peeling branch (from the largest tension to separation; before it the edge springs may
  // still be short of Delta l, where MDR is not JKR by design) the curve is JKR's for the spheres
  int k_max = 200;
  for (int k = 200; k < sep; ++k)
    if (F[k] < F[k_max]) k_max = k;
  int compared = 0;
  for (int k = k_max; k < sep; ++k) {
    const double Fj = jkr.force_of_delta(total[k]);
    CHECK(std::fabs(F[k] - Fj) < 0.01 * std::max(std::fabs(Fj), jkr.pull_off()));
    ++compared;
  }
  CHECK(compared > 20);
  CHECK(imbalance < 1e-9);
}
