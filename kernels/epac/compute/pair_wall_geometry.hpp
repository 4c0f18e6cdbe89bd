#pragma once
// The geometry of a pair or wall contact as the contact kernels see it (compute/contact_forces.hpp,
// compute/pair_lanes.hpp): separation, unit normal, overlap, R* and m*.
#include <epac/core/vec3.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>

namespace epac {

// Index into a model's pair table; one material needs no material loads.
template <class T, class Device>
KOKKOS_FORCEINLINE_FUNCTION int pair_table_index(const Particles<T, Device>& p, int i, int j, int nmat) {
  return nmat == 1 ? 0 : p.material(i) * nmat + p.material(j);
}

// The geometry of pair contact (i, j) and of wall contact (i, wall wl), as the kernels below see
// it (velocity terms and dt are filled by the kernels). Public so that outputs computed outside
// a force pass (the driver's per-contact samples) see exactly the same contact. Periodic axes of
// p.box use the minimum image.
// Mixed precision: separation, distance and overlap are computed from the double positions, and
// only the results (overlap, unit normal) are rounded to T: a float overlap then has float's
// relative accuracy wherever the pair is, instead of the absolute spacing of its coordinates.
// The *_exact forms also return the overlap in double, for the contact-point arms.
namespace detail {
// Centre i minus centre j (minimum image on periodic axes) and its length.
template <class P>
struct PairSeparation {
  Vec3<P> d;
  P dist;
};
template <class T, class Device>
KOKKOS_FORCEINLINE_FUNCTION PairSeparation<typename Particles<T, Device>::position_type> pair_separation(
    const Particles<T, Device>& p, int i, int j) {
  PairSeparation<typename Particles<T, Device>::position_type> s;
  s.d = load3(p.x, i) - load3(p.x, j);
  if (p.box.periodic()) s.d = p.box.minimum_image(s.d);
  s.dist = norm(s.d);
  return s;
}

// The geometry from a separation already taken (the pair kernel tests the overlap first).
template <class T, class Device, bool SideOrder>
KOKKOS_FORCEINLINE_FUNCTION ContactGeometry<T> pair_geometry_from(
    const Particles<T, Device>& p, int i, int j, int nmat,
    const PairSeparation<typename Particles<T, Device>::position_type>& s, double& delta) {
  using P = typename Particles<T, Device>::position_type;
  const Vec3<P>& d = s.d;
  const P dist = s.dist;
  ContactGeometry<T> g;
  g.i = i;
  g.j = j;
  g.pair = pair_table_index(p, i, j, nmat);
  g.R_i = p.radius(i);
  g.R_j = p.radius(j);
  // Coincident centres have no normal; pick x so the law still sees the overlap.
  g.n = dist > P(0) ? vec_cast<T>((P(1) / dist) * d) : Vec3<T>(T(1), T(0), T(0));
  delta = P(g.R_i) + P(g.R_j) - dist;
  g.delta = T(delta);
  g.R_eff = g.R_i * g.R_j / (g.R_i + g.R_j);  // radii > 0 (host validation)
  const T mi = p.mass(i), mj = p.mass(j);
  g.m_eff = mi * mj / (mi + mj);  // masses > 0 (host validation)
  if (SideOrder) g.i_is_first = p.gid(i) < p.gid(j);
  return g;
}

// The overlap and the radii of pair (i, j) only (no normal, R* or m*: none of their three
// divisions), the same bits as pair_geometry_exact's: for passes that need no more (MDR's mean
// surface displacement, mdr_model.hpp).
template <class T, class Device>
KOKKOS_FORCEINLINE_FUNCTION ContactGeometry<T> pair_overlap_geometry(const Particles<T, Device>& p, int i, int j) {
  using P = typename Particles<T, Device>::position_type;
  ContactGeometry<T> g;
  g.i = i;
  g.j = j;
  g.R_i = p.radius(i);
  g.R_j = p.radius(j);
  g.delta = T(P(g.R_i) + P(g.R_j) - pair_separation(p, i, j).dist);
  return g;
}

template <class T, class Device, bool SideOrder>
KOKKOS_FORCEINLINE_FUNCTION ContactGeometry<T> pair_geometry_exact(const Particles<T, Device>& p, int i, int j,
                                                                   int nmat, double& delta) {
  return pair_geometry_from<T, Device, SideOrder>(p, i, j, nmat, pair_separation(p, i, j), delta);
}

// R* of a particle of radius R_i against a wall of curvature R_w (Walls::curvature), as LAMMPS
// computes it for its granular walls (GranularModel::check_contact: Reff = radi radj / (radi +
// radj), radi where radj = 0). Domain: R_w = 0 (flat: R_i), R_w > 0 (convex: R* < R_i) and
// R_w <= -2 R_i (concave: R_i < R* <= 2 R_i). Closer concave radii (the sphere nearly conforming
// to the surface; R* is infinite at R_w = -R_i and negative beyond) are outside a point contact:
// hosts refuse them (validate(particles, walls, model), fix epac/wall), and the kernel clamps
// R_w to -2 R_i there (R* = 2 R_i) so that a radius grown past the validated one (MDR growth)
// keeps R* finite and positive.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T wall_effective_radius(T R_i, T R_w) {
  if (R_w == T(0)) return R_i;
  const T Rw = (R_w < T(0) && R_w > T(-2) * R_i) ? T(-2) * R_i : R_w;
  return R_i * Rw / (R_i + Rw);
}

template <class T, class Device>
KOKKOS_FORCEINLINE_FUNCTION ContactGeometry<T> wall_geometry_exact(const Particles<T, Device>& p,
                                                                   const Walls<T, Device>& w, int i, int wl, int nmat,
                                                                   double& delta) {
  using P = typename Particles<T, Device>::position_type;
  ContactGeometry<T> g;
  g.i = i;
  g.j = -1;
  g.wall = wl;
  g.pair = p.material(i) * nmat + w.material(wl);
  g.n = load3(w.normal, wl);
  const P dist = dot(load3(p.x, i) - load3(w.point, wl), vec_cast<P>(g.n));
  g.R_i = p.radius(i);
  g.R_j = T(0);
  delta = P(g.R_i) - dist;
  g.delta = T(delta);
  g.R_eff = wall_effective_radius(g.R_i, w.curvature(wl));
  g.m_eff = p.mass(i);
  return g;
}
}  // namespace detail

template <class T, class Device, bool SideOrder = true>
KOKKOS_FORCEINLINE_FUNCTION ContactGeometry<T> pair_geometry(const Particles<T, Device>& p, int i, int j, int nmat) {
  double delta;
  return detail::pair_geometry_exact<T, Device, SideOrder>(p, i, j, nmat, delta);
}

template <class T, class Device>
KOKKOS_FORCEINLINE_FUNCTION ContactGeometry<T> wall_geometry(const Particles<T, Device>& p, const Walls<T, Device>& w,
                                                             int i, int wl, int nmat) {
  double delta;
  return detail::wall_geometry_exact(p, w, i, wl, nmat, delta);
}

}  // namespace epac
