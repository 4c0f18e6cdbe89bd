#pragma once
// Velocity-Verlet integration of translation and rotation (docs/design.md section 4, step 5):
//   v += dt/2 (F/m + g),  omega += dt/2 torque / I     (half kick, from the forces of the last pass)
//   x += dt v                                          (drift; in kick_drift)
//   ... contact detection, forces ...
//   v += dt/2 (F/m + g),  omega += dt/2 torque / I     (half kick, from the new forces)
// Positions are double whatever T (mixed precision, state/particles.hpp): the drift adds the
// T velocity times the double dt in double, so a step smaller than a float coordinate's spacing
// still moves the particle.
// Spheres: I = (2/5) m R0^2 (Particles::inertia). Driven particles keep their prescribed
// velocity and angular velocity: they drift but are never kicked.
// kick_drift fuses the closing half kick of one step with the opening half kick and drift of the
// next (kick_dt = dt), the box deformation's remap of the positions, zeroes the consumed forces
// (where the force pass does not overwrite them) and measures the displacement for the rebuild
// rule, all in one pass: 1 parallel region instead of 6, which matters most on busy cores.
#include "driver/box_motion.hpp"

#include <epac/core/simd_lanes.hpp>
#include <epac/core/vec3.hpp>
#include <epac/state/particles.hpp>

namespace epac {
namespace driver {

// mass and inertia are > 0 (the host refuses particle materials without a positive density).
template <class T, class Device>
void half_kick(const Particles<T, Device>& p, const Kokkos::View<unsigned char*, Device>& driven,
               const Vec3<T>& gravity, T half_dt) {
  using exec = typename Device::execution_space;
  auto v = p.v;
  auto w = p.omega;
  auto f = p.force;
  auto tq = p.torque;
  auto m = p.mass;
  auto I = p.inertia;
  Kokkos::parallel_for(
      "epac::driver::half_kick", Kokkos::RangePolicy<exec>(0, p.n), KOKKOS_LAMBDA(int i) {
        if (driven(i)) return;
        const T inv_m = T(1) / m(i);
        const T inv_I = T(1) / I(i);
        v(i, 0) += half_dt * (f(i, 0) * inv_m + gravity.x);
        v(i, 1) += half_dt * (f(i, 1) * inv_m + gravity.y);
        v(i, 2) += half_dt * (f(i, 2) * inv_m + gravity.z);
        for (int d = 0; d < 3; ++d) w(i, d) += half_dt * tq(i, d) * inv_I;
      });
}

// One block of particles of kick_drift (below): copied into lane arrays, updated there with
// selects (driven particles, the remap, the NaN test) and copied back. The compiler vectorises
// the middle loop: the views might alias one another and the reduction's reference (29 streams:
// too many for its run-time alias checks), the lane arrays cannot. Force-inlined, so that a full
// block's loops have the constant trip count W (their copies become vector moves).
template <class T, class Device, int W>
struct KickDriftBlock {
  using P = typename Particles<T, Device>::position_type;
  Particles<T, Device> p;
  Kokkos::View<unsigned char*, Device> driven;
  typename Particles<T, Device>::position_view x_ref;
  Kokkos::View<T*, Device> r_ref;
  AffineRemap<P> remap, ref_map;
  Vec3<T> gravity;
  T kick_dt;
  P dt;
  bool zero_forces;

  // Particles i0 .. i0 + count - 1 (count <= W); s: the running maximum of the rebuild measure.
  KOKKOS_FORCEINLINE_FUNCTION void operator()(int i0, int count, T& s) const {
    P L_x[3][W], L_xr[3][W];
    T L_v[3][W], L_w[3][W], L_f[3][W], L_tq[3][W];
    T L_m[W], L_I[W], L_grow[W], L_shift[W];
    T L_free[W];  // 1 or 0, as T: the vectors' element size
    for (int l = 0; l < count; ++l) {
      const int i = i0 + l;
      for (int d = 0; d < 3; ++d) {
        L_x[d][l] = p.x(i, d);
        L_xr[d][l] = x_ref(i, d);
        L_v[d][l] = p.v(i, d);
        L_w[d][l] = p.omega(i, d);
        L_f[d][l] = p.force(i, d);
        L_tq[d][l] = p.torque(i, d);
      }
      L_m[l] = p.mass(i);
      L_I[l] = p.inertia(i);
      L_grow[l] = p.radius(i) - r_ref(i);
      L_free[l] = driven(i) ? T(0) : T(1);
    }
    const T g[3] = {gravity.x, gravity.y, gravity.z};
    for (int l = 0; l < count; ++l) {
      const bool free = L_free[l] != T(0);
      const T inv_m = T(1) / L_m[l];  // mass and inertia > 0 (the host refuses others)
      const T inv_I = T(1) / L_I[l];
      P e[3];
      for (int d = 0; d < 3; ++d) {
        L_v[d][l] = lane_select(free, L_v[d][l] + kick_dt * (L_f[d][l] * inv_m + g[d]), L_v[d][l]);
        L_w[d][l] = lane_select(free, L_w[d][l] + kick_dt * L_tq[d][l] * inv_I, L_w[d][l]);
        const P xd = lane_select(remap.active, remap(L_x[d][l], d), L_x[d][l]);
        L_x[d][l] = xd + dt * P(L_v[d][l]);
        e[d] = L_x[d][l] - lane_select(ref_map.active, ref_map(L_xr[d][l], d), L_xr[d][l]);
      }
      const T si = T(math::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2])) + lane_max(L_grow[l], T(0));
      L_shift[l] = lane_select(si == si, si, T(1e30));
    }
    for (int l = 0; l < count; ++l)  // apart: a reduction of selects would not vectorise the loop above
      if (L_shift[l] > s) s = L_shift[l];
    for (int l = 0; l < count; ++l) {
      const int i = i0 + l;
      for (int d = 0; d < 3; ++d) {
        p.x(i, d) = L_x[d][l];
        p.v(i, d) = L_v[d][l];
        p.omega(i, d) = L_w[d][l];
      }
    }
    if (zero_forces)
      for (int l = 0; l < count; ++l)
        for (int d = 0; d < 3; ++d) {
          p.force(i0 + l, d) = T(0);
          p.torque(i0 + l, d) = T(0);
        }
  }
};

// v += kick_dt (F/m + g), omega += kick_dt torque/I (not for driven particles); force = torque
// = 0 (unless !zero_forces: the next pass overwrites them, ForceSums::end(true));
// x = remap(x) + dt v in double (remap: a box deformation's affine map, when active).
// Returns max_i (|x_i - ref_map(x_ref_i)| + max(0, R_i - R_ref_i)), the rebuild measure of
// ContactDetector (a non-finite position returns 1e30 so that the rebuild reports it); ref_map:
// the deformation since the reference was taken, so that only the motion beyond it counts
// (ContactDetector::shift_allowance), or inactive (the displacement itself).
// Particles in blocks of particle_lanes (host backends 8, GPUs 1, KickDriftBlock). Each
// particle's arithmetic is the one-particle form's: the result is bitwise the same whatever the
// block and thread count.
template <class T, class Device>
T kick_drift(const Particles<T, Device>& p, const Kokkos::View<unsigned char*, Device>& driven, const Vec3<T>& gravity,
             T kick_dt, typename Particles<T, Device>::position_type dt,
             const typename Particles<T, Device>::position_view& x_ref, const Kokkos::View<T*, Device>& r_ref,
             const AffineRemap<typename Particles<T, Device>::position_type>& remap = {},
             const AffineRemap<typename Particles<T, Device>::position_type>& ref_map = {}, bool zero_forces = true) {
  using exec = typename Device::execution_space;
  constexpr int W = particle_lanes<exec>::value;
  const KickDriftBlock<T, Device, W> block{p, driven, x_ref, r_ref, remap, ref_map, gravity, kick_dt, dt, zero_forces};
  const int n = p.n;
  T shift = T(0);
  Kokkos::parallel_reduce(
      "epac::driver::kick_drift", Kokkos::RangePolicy<exec>(0, (n + W - 1) / W),
      KOKKOS_LAMBDA(int b, T& s) {
        const int i0 = b * W;
        if (n - i0 >= W)
          block(i0, W, s);  // a constant count: the loops unrolled and vectorised
        else
          block(i0, n - i0, s);
      },
      Kokkos::Max<T>(shift));
  return shift;
}

}  // namespace driver
}  // namespace epac
