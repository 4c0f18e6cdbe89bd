#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/core/root_solve.hpp>

#include <cmath>

using namespace epac;

namespace epac_test_root {
// f = x^3 - 8 (one real root at 2): a named functor, callable on the host and the device, so that
// the host test below can hand it to the host-device bracketed_newton (a host lambda there is
// nvcc's error 20013 in a device build).
template <class T>
struct Cubic {
  KOKKOS_INLINE_FUNCTION void operator()(T x, T& f, T& df) const {
    f = x * x * x - T(8);
    df = T(3) * x * x;
  }
};
}  // namespace epac_test_root

TEMPLATE_LIST_TEST_CASE("bracketed Newton finds roots, caps iterations, reports bad brackets", "[core][root]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  Kokkos::View<T*, D> out("out", 6);
  Kokkos::View<int*, D> flags("flags", 6);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        // cubic with one real root at 2 (Newton from the midpoint would overshoot without the bracket)
        auto cubic = [](T x, T& f, T& df) {
          f = x * x * x - T(8);
          df = T(3) * x * x;
        };
        auto r1 = bracketed_newton<T>(cubic, T(0), T(100), T(1e-6));
        out(0) = r1.x;
        flags(0) = r1.converged;
        flags(1) = r1.iters;
        // flat derivative at the start (df = 0 at x = 0): bisection takes over
        auto flat = [](T x, T& f, T& df) {
          f = x * x * x - T(1e-3);
          df = T(3) * x * x;
        };
        auto r2 = bracketed_newton<T>(flat, T(-1), T(1), T(1e-6));
        out(1) = r2.x;
        flags(2) = r2.converged;
        // no sign change: not bracketed, returns the end with the smaller |f|
        auto pos = [](T x, T& f, T& df) {
          f = x * x + T(1);
          df = T(2) * x;
        };
        auto r3 = bracketed_newton<T>(pos, T(1), T(3), T(1e-6));
        out(2) = r3.x;
        flags(3) = r3.bracketed;
        // iteration cap honoured
        auto r4 = bracketed_newton<T>(cubic, T(0), T(100), T(0), 5);
        flags(4) = r4.iters;
        flags(5) = r4.converged;
      });
  auto h = test::to_host(out);
  auto f = test::to_host(flags);
  CHECK(h(0) == Approx(2).epsilon(1e-5));
  CHECK(f(0) == 1);
  CHECK(f(1) < 60);
  CHECK(h(1) == Approx(0.1).epsilon(1e-4));
  CHECK(f(2) == 1);
  CHECK(h(2) == T(1));
  CHECK(f(3) == 0);
  CHECK(f(4) <= 5);
  CHECK(f(5) == 0);
}

// The host-only loop (parameter set-up with std:: maths) takes the same steps as the device loop.
TEMPLATE_TEST_CASE("bracketed_newton_host gives the same bits as bracketed_newton", "[core][root]", float, double) {
  using T = TestType;
  const epac_test_root::Cubic<T> cubic;
  auto flat = [](T x, T& f, T& df) {
    f = std::pow(x, T(3)) - T(1e-3);
    df = T(3) * x * x;
  };  // std:: maths: host only
  for (auto tol : {T(1e-6), T(0)}) {
    const auto a = bracketed_newton<T>(cubic, T(0), T(100), tol, 7);
    const auto b = bracketed_newton_host<T>(cubic, T(0), T(100), tol, 7);
    CHECK(a.x == b.x);
    CHECK(a.iters == b.iters);
    CHECK(a.converged == b.converged);
  }
  const auto r = bracketed_newton_host<T>(flat, T(-1), T(1), T(1e-6));
  CHECK(r.converged);
  CHECK(r.x == Approx(0.1).epsilon(1e-4));
  const auto none = bracketed_newton_host<T>(flat, T(1), T(3), T(1e-6));
  CHECK_FALSE(none.bracketed);
  CHECK(none.x == T(1));
}
