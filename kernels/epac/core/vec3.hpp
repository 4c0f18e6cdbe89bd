#pragma once
// Small 3-vector value type for device code (registers, not views).
#include <epac/core/kokkos_compat.hpp>

namespace epac {

template <class T>
struct Vec3 {
  T x{0}, y{0}, z{0};
  // No KOKKOS_INLINE_FUNCTION: a defaulted constructor is host and device already, and nvcc
  // ignores (and warns, diagnostic 20012) an execution-space annotation on it.
  constexpr Vec3() = default;
  KOKKOS_INLINE_FUNCTION constexpr Vec3(T a, T b, T c) : x(a), y(b), z(c) {}
  KOKKOS_INLINE_FUNCTION T& operator[](int k) { return k == 0 ? x : (k == 1 ? y : z); }
  KOKKOS_INLINE_FUNCTION T operator[](int k) const { return k == 0 ? x : (k == 1 ? y : z); }
  KOKKOS_INLINE_FUNCTION Vec3& operator+=(const Vec3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Vec3& operator-=(const Vec3& o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Vec3& operator*=(T s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
};

template <class T>
KOKKOS_INLINE_FUNCTION Vec3<T> operator+(Vec3<T> a, const Vec3<T>& b) {
  return a += b;
}
template <class T>
KOKKOS_INLINE_FUNCTION Vec3<T> operator-(Vec3<T> a, const Vec3<T>& b) {
  return a -= b;
}
template <class T>
KOKKOS_INLINE_FUNCTION Vec3<T> operator-(const Vec3<T>& a) {
  return Vec3<T>(-a.x, -a.y, -a.z);
}
template <class T>
KOKKOS_INLINE_FUNCTION Vec3<T> operator*(T s, Vec3<T> a) {
  return a *= s;
}
template <class T>
KOKKOS_INLINE_FUNCTION Vec3<T> operator*(Vec3<T> a, T s) {
  return a *= s;
}
template <class T>
KOKKOS_INLINE_FUNCTION T dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
KOKKOS_INLINE_FUNCTION Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return Vec3<T>(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
template <class T>
KOKKOS_INLINE_FUNCTION T norm(const Vec3<T>& a) {
  return math::sqrt(dot(a, a));
}

// Componentwise conversion (mixed precision: double geometry, T results).
template <class U, class T>
KOKKOS_INLINE_FUNCTION Vec3<U> vec_cast(const Vec3<T>& a) {
  return Vec3<U>(U(a.x), U(a.y), U(a.z));
}

// Load / store / atomic-add a row of an (n x 3) view.
template <class View>
KOKKOS_INLINE_FUNCTION Vec3<typename View::non_const_value_type> load3(const View& v, int i) {
  return {v(i, 0), v(i, 1), v(i, 2)};
}
// A row converted to U (a float normal or velocity entering double geometry).
template <class U, class View>
KOKKOS_INLINE_FUNCTION Vec3<U> load3_as(const View& v, int i) {
  return {U(v(i, 0)), U(v(i, 1)), U(v(i, 2))};
}
template <class View, class T>
KOKKOS_INLINE_FUNCTION void store3(const View& v, int i, const Vec3<T>& a) {
  v(i, 0) = a.x;
  v(i, 1) = a.y;
  v(i, 2) = a.z;
}
template <class View, class T>
KOKKOS_INLINE_FUNCTION void atomic_add3(const View& v, int i, const Vec3<T>& a) {
  Kokkos::atomic_add(&v(i, 0), a.x);
  Kokkos::atomic_add(&v(i, 1), a.y);
  Kokkos::atomic_add(&v(i, 2), a.z);
}

}  // namespace epac
