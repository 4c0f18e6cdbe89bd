// core/lane_math.hpp: lane_exp, lane_acos and lane_two_asin_sqrt against libm in ulps over their domains, at the
// ends of the domains (clamps, overflow, underflow, NaN), at the points the contact penalty relies
// on (acos(0) = pi/2 exactly, so that a right angle weighs exactly 1/2), and on a device, where
// the same source runs one value per thread.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/core/lane_math.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace epac;

namespace {

// |a - ref| in units of ref's last place (ref normal and nonzero).
double ulps(double a, double ref) {
  int e = 0;
  std::frexp(ref, &e);
  return std::fabs(a - ref) / std::ldexp(1.0, e - 53);
}

}  // namespace

TEST_CASE("lane_exp: within 1 ulp of libm's exp on [-708, 709]", "[core][lane_math]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> wide(-708.0, 709.0), narrow(-30.0, 30.0), tiny(-1e-6, 1e-6);
  double worst = 0.0, at = 0.0;
  for (int i = 0; i < 3000000; ++i) {
    const double x = i % 3 == 0 ? wide(rng) : (i % 3 == 1 ? narrow(rng) : tiny(rng));
    const double u = ulps(lane_exp(x), std::exp(x));
    if (u > worst) {
      worst = u;
      at = x;
    }
  }
  INFO("worst " << worst << " ulp at x = " << at);
  CHECK(worst <= 1.0);
  // the reduction's edges: x a multiple of ln 2 and half-way between two
  for (int k = -1000; k <= 1000; ++k)
    for (double f : {0.0, 0.5, -0.5, 0.4999999, 0.5000001}) {
      const double x = (k + f) * 0.69314718055994530942;
      if (x < -708.0 || x > 709.0) continue;
      CHECK(ulps(lane_exp(x), std::exp(x)) <= 1.0);
    }
}

TEST_CASE("lane_exp: the ends of its domain", "[core][lane_math]") {
  CHECK(lane_exp(0.0) == 1.0);
  CHECK(lane_exp(-0.0) == 1.0);
  CHECK(lane_exp(1.0) == Approx(std::exp(1.0)).epsilon(2.3e-16));
  CHECK(lane_exp(-708.0) == Approx(std::exp(-708.0)).epsilon(2.3e-16));
  CHECK(lane_exp(709.0) == Approx(std::exp(709.0)).epsilon(2.3e-16));
  CHECK(lane_exp(-708.5) == 0.0);  // below the normal range: 0, not a subnormal
  CHECK(lane_exp(-1e300) == 0.0);
  CHECK(lane_exp(-std::numeric_limits<double>::infinity()) == 0.0);
  CHECK(std::isinf(lane_exp(709.9)));
  CHECK(std::isinf(lane_exp(std::numeric_limits<double>::infinity())));
  CHECK(std::isnan(lane_exp(std::numeric_limits<double>::quiet_NaN())));
  CHECK(lane_exp(1.5f) == Approx(std::exp(1.5)).epsilon(1.2e-7));
}

TEST_CASE("lane_acos: within 2 ulp of libm's acos on [-1, 1], clamped outside", "[core][lane_math]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> all(-1.0, 1.0), near_one(1.0 - 1e-6, 1.0), near_half(0.5 - 1e-9, 0.5 + 1e-9);
  double worst = 0.0, at = 0.0;
  for (int i = 0; i < 3000000; ++i) {
    double x = i % 3 == 0 ? all(rng) : (i % 3 == 1 ? near_one(rng) : near_half(rng));
    if (i % 2) x = -x;
    const double ref = std::acos(x);
    if (ref == 0.0) continue;
    const double u = ulps(lane_acos(x), ref);
    if (u > worst) {
      worst = u;
      at = x;
    }
  }
  INFO("worst " << worst << " ulp at x = " << at);
  CHECK(worst <= 2.0);
  CHECK(lane_acos(0.0) == 0.5 * constants<double>::pi);  // exactly: a right angle's penalty term is 1/2
  CHECK(lane_acos(-0.0) == 0.5 * constants<double>::pi);
  CHECK(lane_acos(1.0) == 0.0);
  CHECK(lane_acos(-1.0) == constants<double>::pi);
  CHECK(lane_acos(0.5) == Approx(std::acos(0.5)).epsilon(4.5e-16));
  CHECK(lane_acos(-0.5) == Approx(std::acos(-0.5)).epsilon(4.5e-16));
  // the guard: a cosine an ulp outside [-1, 1]
  CHECK(lane_acos(1.0000000000000002) == 0.0);
  CHECK(lane_acos(-1.0000000000000002) == constants<double>::pi);
  CHECK(lane_acos(7.0) == 0.0);
  CHECK(std::isnan(lane_acos(std::numeric_limits<double>::quiet_NaN())));
  CHECK(lane_acos(0.25f) == Approx(std::acos(0.25)).epsilon(1.2e-7));
}

TEST_CASE("lane_two_asin_sqrt: within 2 ulp of 2 asin(sqrt x) on [0, 1], clamped outside", "[core][lane_math]") {
  // reference in long double, from the exact x: 2 asin(sqrt x) below 1/2, pi - 2 asin(sqrt(1 - x))
  // above (1 - x is exact there; 2 asin(sqrt x) of a rounded root is ill-conditioned near x = 1)
  const auto ref_of = [](double x) {
    const long double xl = x;
    return x <= 0.5 ? 2.0L * std::asin(std::sqrt(xl))
                    : 3.14159265358979323846264338327950288L - 2.0L * std::asin(std::sqrt(1.0L - xl));
  };
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> all(0.0, 1.0), tiny(0.0, 1e-6), q1(0.25 - 1e-9, 0.25 + 1e-9),
      q3(0.75 - 1e-9, 0.75 + 1e-9), one(1.0 - 1e-6, 1.0);
  double worst = 0.0, at = 0.0;
  for (int i = 0; i < 3000000; ++i) {
    double x =
        i % 5 == 0 ? all(rng) : (i % 5 == 1 ? tiny(rng) : (i % 5 == 2 ? q1(rng) : (i % 5 == 3 ? q3(rng) : one(rng))));
    if (i % 7 == 0) x = std::ldexp(all(rng), -int(rng() % 1000));  // down to the subnormals
    const long double ref = ref_of(x);
    if (ref == 0.0L) continue;
    const double u = ulps(lane_two_asin_sqrt(x, std::sqrt(x), std::sqrt(1.0 - x)), double(ref));
    if (u > worst) {
      worst = u;
      at = x;
    }
  }
  INFO("worst " << worst << " ulp at x = " << at);
  CHECK(worst <= 2.0);
  CHECK(lane_two_asin_sqrt(0.0, 0.0, 1.0) == 0.0);
  CHECK(lane_two_asin_sqrt(1.0, 1.0, 0.0) == constants<double>::pi);
  CHECK(lane_two_asin_sqrt(0.5, std::sqrt(0.5), std::sqrt(0.5)) == 0.5 * constants<double>::pi);
  CHECK(lane_two_asin_sqrt(0.25, 0.5, std::sqrt(0.75)) == Approx(2.0 * std::asin(0.5)).epsilon(4.5e-16));
  CHECK(lane_two_asin_sqrt(0.75, std::sqrt(0.75), 0.5) ==
        Approx(constants<double>::pi - 2.0 * std::asin(0.5)).epsilon(4.5e-16));
  // tiny x: 2 sqrt(x) to the last bit, where acos(1 - 2x) would have rounded x away
  CHECK(lane_two_asin_sqrt(1e-300, 1e-150, 1.0) == 2e-150);
  // the clamp: an x an ulp outside [0, 1] with the roots of the clamped x
  CHECK(lane_two_asin_sqrt(1.0000000000000002, 1.0, 0.0) == constants<double>::pi);
  CHECK(lane_two_asin_sqrt(-1e-300, 0.0, 1.0) == 0.0);
  CHECK(std::isnan(lane_two_asin_sqrt(std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0)));
  CHECK(lane_two_asin_sqrt(0.3f, std::sqrt(0.3f), std::sqrt(0.7f)) ==
        Approx(2.0 * std::asin(std::sqrt(0.3))).epsilon(1.2e-7));
}

TEMPLATE_LIST_TEST_CASE("lane_exp and lane_acos: a device gives the host's values", "[core][lane_math]",
                        test::Backends) {
  using D = TestType;
  using exec = typename D::execution_space;
  const int n = 4096;
  Kokkos::View<double*, D> x("x", n), e("e", n), a("a", n);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
        const double xi = -1.0 + 2.0 * (i + 0.5) / n;
        x(i) = xi;
        e(i) = lane_exp(40.0 * xi);
        a(i) = lane_acos(xi);
      });
  auto hx = test::to_host(x);
  auto he = test::to_host(e);
  auto ha = test::to_host(a);
  for (int i = 0; i < n; ++i) {
    INFO("x = " << hx(i));
    // FMA contraction may differ between a device's compiler and the host's: a few ulp
    CHECK(he(i) == Approx(lane_exp(40.0 * hx(i))).epsilon(1e-15));
    CHECK(ha(i) == Approx(lane_acos(hx(i))).epsilon(1e-15));
    CHECK(ulps(he(i), std::exp(40.0 * hx(i))) <= 2.0);
  }
}
