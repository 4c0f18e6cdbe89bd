// detail/mdr_side_lane.hpp: the branch-free common path of MDR's side law (a yielded side below its
// delta_max on its stored shape) against mdr_side_force, on every backend and scalar type: the
// same values within a few ulp where it applies (the ellipse's angle is lane_two_asin_sqrt, not
// libm's asin), the side's state unchanged there, and every other regime flagged rare with finite
// placeholders.
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>
#include <epac/models/mdr/detail/mdr_side_lane.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace epac;
using namespace epac::test;

namespace {

// One side evaluation to compare: the inputs, then both forms' results.
template <class T>
struct SideCase {
  T delta, R, growth;
  MdrSideState<T> state;
};
template <class T>
struct SideBoth {
  MdrSideLane<T> lane;
  MdrSideResult<T> scalar;
  MdrSideState<T> after;  // the state mdr_side_force left
};

// Both forms of every case in one kernel on D.
template <class D, class T>
std::vector<SideBoth<T>> evaluate_both(const MdrSideConstants<T>& c, const std::vector<SideCase<T>>& cases) {
  using exec = typename D::execution_space;
  const int n = int(cases.size());
  Kokkos::View<SideCase<T>*, D> in("cases", n);
  Kokkos::View<SideBoth<T>*, D> out("both", n);
  auto hin = Kokkos::create_mirror_view(in);
  for (int k = 0; k < n; ++k) hin(k) = cases[k];
  Kokkos::deep_copy(in, hin);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int k) {
        const SideCase<T> sc = in(k);
        SideBoth<T> b;
        b.lane = mdr_side_force_lane(c, sc.delta, sc.R, sc.growth, sc.state);
        b.after = sc.state;
        b.scalar = mdr_side_force<true, false>(c, T(0), T(1), sc.delta, sc.R, sc.growth, b.after, T(1), false);
        out(k) = b;
      });
  auto hout = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out);
  return std::vector<SideBoth<T>>(hout.data(), hout.data() + n);
}

// The state of a side loaded plastically to delta_max (in 60 steps, the last storing its shape), R
// and growth fixed.
template <class T>
MdrSideState<T> loaded_to(const MdrSideConstants<T>& c, T delta_max, T R, T growth) {
  MdrSideState<T> s;
  for (int i = 1; i <= 60; ++i)
    mdr_side_force<true, false>(c, T(0), T(1), T(delta_max * i / 60), R, growth, s, T(1), false);
  return s;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("MDR side lane form: the common path is mdr_side_force's within a few ulp",
                        "[mdr][side][lanes]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const bool dbl = sizeof(T) >= 8;
  // F near delta_p is a small difference of the bracket's terms: compared against the side's
  // largest force; float's own rounding of the inputs and the roots sets its bound
  const double tol_F = dbl ? 1e-13 : 2e-5, tol_exact = dbl ? 4e-16 : 4e-7;
  const double E = 1e9;
  for (double EY : {25.0, 200.0, 1000.0}) {
    const auto c = side_constants<T>(E, kNu, E / EY, MdrYieldOnset::hertz_40);
    std::vector<SideCase<T>> cases;
    std::vector<double> F_scale;
    for (double R0 : {0.9e-3, 1.0e-3, 1.1e-3})
      for (double grow : {0.0, 0.02}) {  // growth R - R_o shifts delta_max by (19)
        const T R = T(R0 * (1.0 + grow)), growth = T(R0 * grow);
        for (double m : {0.05, 0.2, 0.45}) {
          const T dmax = T(m * R0) + growth;
          const MdrSideState<T> s = loaded_to(c, dmax, R, growth);
          REQUIRE(s.yielded == T(1));
          REQUIRE(s.shape_R == R);
          const double Fmax = double(c.E_eff) * R0 * R0;  // above the side's largest force
          // unloading below delta_max: the bracket's direct and series forms (theta < 0.25 near
          // delta_p), and past delta_p (d1De <= 0: no force)
          for (double f : {1e-12, 1e-9, 1e-6, 1e-4, 1e-3, 1e-2, 3e-2, 0.1, 0.3, 0.6, 1.0}) {
            const T delta = T(double(dmax) * (1.0 - f));
            if (!(delta < dmax)) continue;  // float: 1 - 1e-9 rounds to 1, which is loading
            cases.push_back({delta, R, growth, s});
            F_scale.push_back(Fmax);
          }
          // between delta_p and delta_max, evenly (the elastic retrace)
          const double dp = double(s.delta_p), top = double(dmax);
          for (int i = 1; i < 40; ++i) {
            cases.push_back({T(dp + (top - dp) * i / 40.0), R, growth, s});
            F_scale.push_back(Fmax);
          }
        }
      }
    const auto both = evaluate_both<D, T>(c, cases);
    int touching = 0, series = 0;
    for (std::size_t k = 0; k < both.size(); ++k) {
      const SideCase<T>& sc = cases[k];
      const SideBoth<T>& b = both[k];
      INFO("E/Y = " << EY << ", R = " << sc.R << ", delta = " << sc.delta << ", delta_max = " << b.scalar.delta_max
                    << ", d1De/A = " << b.scalar.d1De / b.scalar.A);
      REQUIRE(b.lane.rare == T(0));
      REQUIRE(b.scalar.plastic);
      REQUIRE_FALSE(b.scalar.loading);
      CHECK(std::fabs(double(b.lane.F) - double(b.scalar.F)) <= tol_F * F_scale[k]);
      if (b.scalar.F > T(0))
        CHECK(std::fabs(double(b.lane.F) - double(b.scalar.F)) <= 1e3 * tol_F * double(b.scalar.F));
      const auto near = [&](T x, T ref) {
        return std::fabs(double(x) - double(ref)) <= tol_exact * std::fabs(double(ref));
      };
      CHECK(near(b.lane.a, b.scalar.a));
      CHECK(near(b.lane.area, b.scalar.area));
      CHECK(near(b.lane.d1De, b.scalar.d1De));
      CHECK(b.lane.delta_max == b.scalar.delta_max);
      // the common path leaves the state as it was (so the lane form writes none)
      CHECK(b.after.delta_o_max == sc.state.delta_o_max);
      CHECK(b.after.yielded == sc.state.yielded);
      CHECK(b.after.c_A == sc.state.c_A);
      CHECK(b.after.delta_p == sc.state.delta_p);
      CHECK(b.after.shape_A == sc.state.shape_A);
      CHECK(b.after.shape_R == sc.state.shape_R);
      CHECK(b.after.shape_delta_max == sc.state.shape_delta_max);
      touching += b.scalar.F > T(0);
      series += b.scalar.F > T(0) && b.scalar.d1De / b.scalar.A < T(0.0155);  // theta < 0.25
    }
    // the cases reach both forms of the bracket and the released end
    CHECK(touching > 0);
    CHECK(series > 0);
    CHECK(touching < int(both.size()));
  }
}

TEMPLATE_LIST_TEST_CASE("MDR side lane form: every other regime is rare, with finite values", "[mdr][side][lanes]",
                        BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double E = 1e9, R0 = 1e-3;
  const auto c = side_constants<T>(E, kNu, E / 200.0, MdrYieldOnset::hertz_40);
  const auto elastic = side_constants<T>(E, kNu, std::numeric_limits<double>::infinity());
  const T R = T(R0), dmax = T(0.2 * R0);
  const MdrSideState<T> s = loaded_to(c, dmax, R, T(0));
  std::vector<SideCase<T>> cases;
  cases.push_back({dmax, R, T(0), s});                            // at delta_max: plastic loading
  cases.push_back({T(1.01) * dmax, R, T(0), s});                  // past it: plastic loading
  cases.push_back({T(0.99) * dmax, T(1.001) * R, T(0), s});       // R moved: the stored shape misses
  cases.push_back({T(0.99) * dmax, R, T(1e-7), s});               // growth moved delta_max: misses
  cases.push_back({T(0.99) * dmax, R, T(0), MdrSideState<T>{}});  // never yielded
  MdrSideState<T> empty_shape = s;
  empty_shape.shape_R = T(0);  // a released contact's zeroed shape
  cases.push_back({T(0.99) * dmax, R, T(0), empty_shape});
  const auto both = evaluate_both<D, T>(c, cases);
  for (std::size_t k = 0; k < both.size(); ++k) {
    INFO("case " << k);
    CHECK(both[k].lane.rare == T(1));
    CHECK(std::isfinite(double(both[k].lane.F)));
    CHECK(std::isfinite(double(both[k].lane.a)));
    CHECK(std::isfinite(double(both[k].lane.d1De)));
  }
  // an elastic material's side: never yields, always rare
  std::vector<SideCase<T>> el;
  MdrSideState<T> es;
  for (int i = 1; i <= 20; ++i)
    mdr_side_force<true, false>(elastic, T(0), T(1), T(0.01 * R0 * i), R, T(0), es, T(1), false);
  el.push_back({T(0.1 * R0), R, T(0), es});
  el.push_back({T(0.3 * R0), R, T(0), es});
  for (const auto& b : evaluate_both<D, T>(elastic, el)) {
    CHECK(b.lane.rare == T(1));
    CHECK(std::isfinite(double(b.lane.F)));
  }
}

TEMPLATE_LIST_TEST_CASE("MDR ellipse: the bracket's lane form is the scalar one's within a few ulp", "[mdr][lanes]",
                        test::Backends) {
  using D = TestType;
  using exec = typename D::execution_space;
  const int n = 20001;
  Kokkos::View<double*, D> x("x", n), lane("lane", n), scalar("scalar", n);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
        // [0, 1] evenly, and the series' end (theta = 0.25 at x = sin^2(0.125)) densely
        const double xi = i < 10001 ? i / 10000.0 : 0.0155 + 1e-4 * (i - 10001) / 10000.0;
        x(i) = xi;
        lane(i) = mdr_ellipse_bracket_of_depth_lane(xi);
        scalar(i) = mdr_ellipse_bracket_of_depth(xi);
      });
  auto hx = test::to_host(x);
  auto hl = test::to_host(lane);
  auto hs = test::to_host(scalar);
  for (int i = 0; i < n; ++i) {
    INFO("x = " << hx(i));
    // the bracket's cancellation near theta = 0.25 turns the angle's 2 ulp into about 50
    CHECK(std::fabs(hl(i) - hs(i)) <= 1.2e-14 * std::fabs(hs(i)));
  }
  CHECK(mdr_ellipse_bracket_of_depth_lane(0.5) == 0.5 * constants<double>::pi);  // the equator, exactly
  CHECK(mdr_ellipse_bracket_of_depth_lane(0.0) == 0.0);
  CHECK(mdr_ellipse_bracket_of_depth_lane(1.0) == Approx(constants<double>::pi).epsilon(1e-15));
  CHECK(mdr_ellipse_bracket_of_depth_lane(1.5) == mdr_ellipse_bracket_of_depth_lane(1.0));  // clamped
  CHECK(mdr_ellipse_bracket_of_depth_lane(-0.5) == 0.0);
}
