#pragma once
// Mindlin-type tangential spring with Coulomb limit, Nan (21)-(23), with viscous damping
// Nan (25). The history is the tangential displacement delta_t (3 fields), rotated into the
// current tangent plane every step with its length kept (the contact plane turns as the
// particles roll and orbit).
#include <epac/core/simd_lanes.hpp>
#include <epac/core/vec3.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/state/contact_history.hpp>

namespace epac {

// Sliding, Nan (23): the trial force ft (|ft|^2 = ft2 > f_lim^2 >= 0) exceeds the Coulomb
// limit f_lim = mu |f|. |F_t| = f_lim along -delta_t, no viscous part; the spring xi is
// shortened to the length that carries exactly that force.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION void coulomb_slide(Vec3<T>& ft, Vec3<T>& xi, T f_lim, T ft2, T k_t) {
  const T xi2 = dot(xi, xi);
  if (xi2 > T(0) && k_t > T(0)) {
    const Vec3<T> dir = (T(1) / math::sqrt(xi2)) * xi;
    ft = T(-1) * f_lim * dir;
    xi = (f_lim / k_t) * dir;
  } else {
    // No spring direction (k_t == 0 or xi == 0): the damping alone exceeded the limit
    // (ft2 > f_lim^2 >= 0, so the sqrt is of a positive number).
    ft = (f_lim / math::sqrt(ft2)) * ft;
    xi = Vec3<T>();
  }
}

// The sticking step of tangential_spring_force below without branches, for contacts in lanes
// (compute/pair_lanes.hpp: the same arithmetic, selects instead of tests, so each lane gets the
// bits of the scalar form). xi: the history in the frame of the pair's orientation; returns it
// rotated and advanced, and the trial force. The caller applies coulomb_slide where
// |ft|^2 > f_lim^2 (rare: outside the vectorised part). Values in and out, no references: a
// lane's variables then stay in registers, which the vectoriser needs.
// Domain: the rescale's quotient len2_old / len2_new is used only where len2_new > 0 (a
// denominator of 1 elsewhere, whose result the select discards).
template <class T>
struct TangentialTrial {
  Vec3<T> xi, ft;
};
template <class T>
KOKKOS_FORCEINLINE_FUNCTION TangentialTrial<T> tangential_trial(Vec3<T> xi, const Vec3<T>& n, const Vec3<T>& v_t, T k_t,
                                                                T damp_t, T dt) {
  const T xn = dot(xi, n);
  const T len2_old = dot(xi, xi);
  const Vec3<T> in_plane = xi - xn * n;
  const T len2_new = dot(in_plane, in_plane);
  const bool turn = xn != T(0);
  const bool rescale = turn & (len2_new > T(0));  // & not &&: no branch
  const T scale = math::sqrt(len2_old / lane_select(len2_new > T(0), len2_new, T(1)));
  xi.x = lane_select(rescale, scale * in_plane.x, lane_select(turn, in_plane.x, xi.x));
  xi.y = lane_select(rescale, scale * in_plane.y, lane_select(turn, in_plane.y, xi.y));
  xi.z = lane_select(rescale, scale * in_plane.z, lane_select(turn, in_plane.z, xi.z));
  xi += dt * v_t;
  return {xi, T(-1) * k_t * xi - damp_t * v_t};  // Nan (21) + (25)
}

// Returns the tangential force on particle i. v_t is the tangential relative velocity of i's
// contact point with respect to j's (or the wall's). `normal_force` is the law's normal force f
// (Nan (23) uses f, without damping); the Coulomb bound is mu |f|, so adhesive tension counts.
// damp_t: the viscous coefficient of Nan (25) times sqrt(m* k_t) (0 without damping).
// orient (+1 or -1): the history holds delta_t of the contact's particle with the smaller global
// id relative to the other, so that it survives a list that names the pair the other way round
// (after a rebuild that renumbered the particles); orient = -1 when particle i is the larger id.
// Hot path: one sqrt while the contact sticks (the rescale after the rotation), magnitudes
// compared squared; the sliding branch adds one more.
template <class T, class Row>
KOKKOS_FORCEINLINE_FUNCTION Vec3<T> tangential_spring_force(const NormalForce<T>& nf, const Vec3<T>& n,
                                                            const Vec3<T>& v_t, T damp_t, T dt, const Row& h,
                                                            T orient = T(1)) {
  Vec3<T> xi = orient * Vec3<T>(h(0), h(1), h(2));  // exact: orient is +-1
  // Rotate into the current tangent plane, keeping |xi|: xi - (xi.n) n, scaled by
  // sqrt(|xi|^2 / |xi - (xi.n) n|^2) (domain: the quotient is >= 1 and finite when len2_new > 0).
  const T xn = dot(xi, n);
  if (xn != T(0)) {
    const T len2_old = dot(xi, xi);
    xi -= xn * n;
    const T len2_new = dot(xi, xi);
    if (len2_new > T(0)) xi *= math::sqrt(len2_old / len2_new);
  }
  xi += dt * v_t;
  Vec3<T> ft = T(-1) * nf.k_t * xi - damp_t * v_t;  // Nan (21) + (25): opposes the displacement
  const T f_lim = nf.mu * math::fabs(nf.f);
  const T ft2 = dot(ft, ft);
  if (ft2 > f_lim * f_lim) coulomb_slide(ft, xi, f_lim, ft2, nf.k_t);
  h(0) = orient * xi.x;
  h(1) = orient * xi.y;
  h(2) = orient * xi.z;
  return ft;
}

template <class Row>
KOKKOS_INLINE_FUNCTION void reset_tangential(const Row& h) {
  h(0) = 0;
  h(1) = 0;
  h(2) = 0;
}

}  // namespace epac
