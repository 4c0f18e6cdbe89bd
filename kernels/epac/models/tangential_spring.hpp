#pragma once
// Mindlin-type tangential spring with Coulomb limit, Nan (21)-(23), with viscous damping
// Nan (25). The history is the tangential displacement delta_t (3 fields), rotated into the
// current tangent plane every step with its length kept (the contact plane turns as the
// particles roll and orbit).
#include <epac/core/vec3.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/state/contact_history.hpp>

namespace epac {

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
  if (ft2 > f_lim * f_lim) {
    // Sliding, Nan (23): |F_t| = mu |f| along -delta_t, no viscous part; the spring is
    // shortened to the length that carries exactly that force.
    const T xi2 = dot(xi, xi);
    if (xi2 > T(0) && nf.k_t > T(0)) {
      const Vec3<T> dir = (T(1) / math::sqrt(xi2)) * xi;
      ft = T(-1) * f_lim * dir;
      xi = (f_lim / nf.k_t) * dir;
    } else {
      // No spring direction (k_t == 0 or xi == 0): the damping alone exceeded the limit
      // (ft2 > f_lim^2 >= 0, so the sqrt is of a positive number).
      ft = (f_lim / math::sqrt(ft2)) * ft;
      xi = Vec3<T>();
    }
  }
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
