#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/core/kokkos_compat.hpp>
#include <epac/core/vec3.hpp>

#include <cmath>
#include <limits>

using namespace epac;

TEMPLATE_LIST_TEST_CASE("math shim evaluates on every backend", "[core]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  Kokkos::View<T*, D> out("out", 12);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        out(0) = math::sqrt(T(4));
        out(1) = math::cbrt(T(27));
        out(2) = math::acos(T(-1));
        out(3) = math::acos_clamped(T(1.0000001));  // just outside the domain: clamped to 1
        out(4) = math::sqrt_nonneg(T(-1e-20));      // round-off below zero: 0, not NaN
        out(5) = math::clamp(T(5), T(0), T(1));
        out(6) = math::min(T(2), T(-3));
        out(7) = math::max(T(2), T(-3));
        out(8) = math::safe_div(T(1), T(0), T(1e-3));
        out(9) = math::pow(T(2), T(10));
        out(10) = norm(cross(Vec3<T>(1, 0, 0), Vec3<T>(0, 1, 0)));
        out(11) = math::log(math::exp(T(1.5)));
      });
  auto h = test::to_host(out);
  const double tol = std::is_same<T, float>::value ? 1e-6 : 1e-14;
  CHECK(h(0) == Approx(2).epsilon(tol));
  CHECK(h(1) == Approx(3).epsilon(tol));
  CHECK(h(2) == Approx(constants<double>::pi).epsilon(tol));
  CHECK(h(3) == T(0));
  CHECK(h(4) == T(0));
  CHECK(h(5) == T(1));
  CHECK(h(6) == T(-3));
  CHECK(h(7) == T(2));
  CHECK(h(8) == Approx(1000).epsilon(tol));
  CHECK(h(9) == Approx(1024).epsilon(tol));
  CHECK(h(10) == Approx(1).epsilon(tol));
  CHECK(h(11) == Approx(1.5).epsilon(tol));
}

TEST_CASE("host mirror type is the mirror of the view", "[core]") {
  Kokkos::View<double*> v("v", 3);
  host_mirror_t<Kokkos::View<double*>> h = Kokkos::create_mirror_view(v);
  h(2) = 4.0;
  Kokkos::deep_copy(v, h);
  auto back = test::to_host(v);
  CHECK(back(2) == 4.0);
  STATIC_REQUIRE(std::is_same<typename decltype(h)::memory_space, Kokkos::HostSpace>::value);
}
