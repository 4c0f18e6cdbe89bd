#pragma once
// A periodic box for the contact geometry: along each periodic axis the separation of two
// particles is taken as its minimum image. Positions must be wrapped into the box (the host does
// that; the driver after every drift), so a raw separation lies in (-L, L) and one conditional
// shift gives the minimum image: no division, no rounding call on the hot path. The image is
// the right one while every interaction distance is below L/2 (the host checks it).
// Affine deformation (LAMMPS `fix deform ... remap x`) only changes `length` between passes.
#include <epac/core/simd_lanes.hpp>
#include <epac/core/vec3.hpp>

namespace epac {

template <class T>
struct PeriodicBox {
  Vec3<T> lo;      // lower corner
  Vec3<T> length;  // edge along each axis; 0 = that axis is not periodic

  KOKKOS_INLINE_FUNCTION bool periodic() const { return length.x > T(0) || length.y > T(0) || length.z > T(0); }

  // One axis: s in (-L, L) -> its image in [-L/2, L/2]. L == 0 leaves s unchanged.
  KOKKOS_FORCEINLINE_FUNCTION static T image(T s, T L) {
    const T h = T(0.5) * L;
    return s > h ? s - L : (s < -h ? s + L : s);
  }
  // image() as bit selects, for contacts in lanes (compute/pair_lanes.hpp): the same result bits,
  // no branch; with L = 0 (an open axis) s itself (s - 0 and s + 0 are s), so it needs no test
  // of the axis either.
  KOKKOS_FORCEINLINE_FUNCTION static T image_select(T s, T L) {
    const T h = T(0.5) * L;
    return lane_select(s > h, s - L, lane_select(s < -h, s + L, s));
  }
  KOKKOS_FORCEINLINE_FUNCTION Vec3<T> minimum_image(const Vec3<T>& d) const {
    return Vec3<T>(length.x > T(0) ? image(d.x, length.x) : d.x, length.y > T(0) ? image(d.y, length.y) : d.y,
                   length.z > T(0) ? image(d.z, length.z) : d.z);
  }
  // Wraps a coordinate into [lo, lo + L) along a periodic axis (positions may have left the box
  // by less than one box length in one drift).
  KOKKOS_INLINE_FUNCTION static T wrap(T x, T lo_d, T L) {
    if (!(L > T(0))) return x;
    if (x >= lo_d + L)
      x -= L;
    else if (x < lo_d)
      x += L;
    // far outside (a particle that moved more than a box length): fold exactly
    if (x < lo_d || x >= lo_d + L) {
      x = x - L * math::floor((x - lo_d) / L);
      if (x >= lo_d + L) x = lo_d;  // round-off at the upper edge
    }
    return x;
  }
};

}  // namespace epac
