#pragma once
// Kokkos compatibility shim (docs/design.md section 9): one spelling for everything that moved
// between Kokkos 3.4 and 5.x. Kernels use epac::math::* and epac::host_mirror_t, never the
// version-specific names.
#include <Kokkos_Core.hpp>

#include <cstdint>
#include <memory>
#include <type_traits>

#if KOKKOS_VERSION >= 30700
#define EPAC_KOKKOS_MATH_NS Kokkos
#else
#define EPAC_KOKKOS_MATH_NS Kokkos::Experimental
#endif

namespace epac {
namespace math {

#define EPAC_UNARY(FN)                                                 \
  template <class T>                                                   \
  KOKKOS_INLINE_FUNCTION T FN(T x) {                                   \
    static_assert(std::is_floating_point<T>::value, "floating point"); \
    return EPAC_KOKKOS_MATH_NS::FN(x);                                 \
  }
EPAC_UNARY(sqrt)
EPAC_UNARY(cbrt)
EPAC_UNARY(exp)
EPAC_UNARY(log)
EPAC_UNARY(acos)
EPAC_UNARY(asin)
EPAC_UNARY(atan)
EPAC_UNARY(cos)
EPAC_UNARY(sin)
EPAC_UNARY(fabs)
EPAC_UNARY(floor)
#undef EPAC_UNARY

template <class T>
KOKKOS_INLINE_FUNCTION T pow(T x, T y) {
  return EPAC_KOKKOS_MATH_NS::pow(x, y);
}
template <class T>
KOKKOS_INLINE_FUNCTION T atan2(T y, T x) {
  return EPAC_KOKKOS_MATH_NS::atan2(y, x);
}
template <class T>
KOKKOS_INLINE_FUNCTION bool isfinite(T x) {
  return EPAC_KOKKOS_MATH_NS::isfinite(x);
}

// min/max/clamp: absent before Kokkos 3.6, so they are ours everywhere.
template <class T>
KOKKOS_INLINE_FUNCTION constexpr T min(T a, T b) {
  return b < a ? b : a;
}
template <class T>
KOKKOS_INLINE_FUNCTION constexpr T max(T a, T b) {
  return a < b ? b : a;
}
template <class T>
KOKKOS_INLINE_FUNCTION constexpr T clamp(T x, T lo, T hi) {
  return x < lo ? lo : (hi < x ? hi : x);
}

// Domain-guarded forms: each clamps its argument into the function's domain. Use them where
// round-off can push an argument that is mathematically inside the domain just outside it.
template <class T>
KOKKOS_INLINE_FUNCTION T sqrt_nonneg(T x) {
  return EPAC_KOKKOS_MATH_NS::sqrt(x > T(0) ? x : T(0));
}
template <class T>
KOKKOS_INLINE_FUNCTION T acos_clamped(T x) {
  return EPAC_KOKKOS_MATH_NS::acos(clamp(x, T(-1), T(1)));
}
// a / b with |b| bounded away from zero by tiny (sign of b kept; b == 0 treated as positive).
template <class T>
KOKKOS_INLINE_FUNCTION T safe_div(T a, T b, T tiny) {
  const T mag = fabs(b) > tiny ? b : (b < T(0) ? -tiny : tiny);
  return a / mag;
}

template <class T>
KOKKOS_INLINE_FUNCTION constexpr T sign(T x) {
  return x < T(0) ? T(-1) : T(1);
}

}  // namespace math

template <class T>
struct constants {
  static constexpr T pi = T(3.14159265358979323846264338327950288);
  // machine epsilon of float or double (Kokkos's numeric traits are not in every version we support)
  static constexpr T epsilon = sizeof(T) == sizeof(float) ? T(1.1920928955078125e-7) : T(2.220446049250313e-16);
};

// Host mirror type, spelled the same way on every Kokkos version.
template <class View>
using host_mirror_t = decltype(Kokkos::create_mirror_view(std::declval<View>()));

// Host: Kokkos::ScopeGuard with a thread count (<= 0: Kokkos's default, i.e. OMP_NUM_THREADS for
// OpenMP). InitArguments became InitializationSettings in Kokkos 3.7.
inline std::unique_ptr<Kokkos::ScopeGuard> start_kokkos(int threads) {  // host
#if KOKKOS_VERSION >= 30700
  Kokkos::InitializationSettings settings;
  if (threads > 0) settings.set_num_threads(threads);
  return std::make_unique<Kokkos::ScopeGuard>(settings);  // host
#else
  Kokkos::InitArguments args;
  if (threads > 0) args.num_threads = threads;
  return std::make_unique<Kokkos::ScopeGuard>(args);  // host
#endif
}

// Default device for epac containers.
using DefaultDevice = Kokkos::Device<Kokkos::DefaultExecutionSpace, Kokkos::DefaultExecutionSpace::memory_space>;

}  // namespace epac
