#pragma once
// The part of a contact's evaluation shared by the contact kernels (compute/contact_forces.hpp,
// compute/pair_lanes.hpp): the law, damping, friction, rolling resistance and accumulation of
// one contact whose geometry is known, and the tail of a contact the law found inactive.
#include <epac/compute/contact_outputs.hpp>
#include <epac/compute/pair_wall_geometry.hpp>
#include <epac/compute/particle_sums.hpp>
#include <epac/core/vec3.hpp>
#include <epac/models/contact_conventions.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/models/model_interface.hpp>
#include <epac/models/rolling_resistance.hpp>
#include <epac/models/tangential_spring.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/particles.hpp>

namespace epac {

namespace detail {

// A contact the law found inactive: its tangential and rolling history forgotten, zero outputs.
template <class Model, class T, class Device>
KOKKOS_FORCEINLINE_FUNCTION void finish_inactive(const HistoryRow<T, Device>& row, T delta,
                                                 const ContactOutputs<T, Device>& out,
                                                 const ContactForceBuffer<T, Device>& buf, int k) {
  const auto trow = row.shifted(Model::normal_history_size);
  if (Model::effects::friction) reset_tangential(trow);
  if (detail::rolling_on<Model>::value) reset_rolling(trow.shifted(Model::effects::friction ? 3 : 0));
  if (out.normal_force.extent(0) > 0) out.normal_force(k) = T(0);
  if (out.overlap.extent(0) > 0) out.overlap(k) = delta;
  if (buf.enabled()) {
    store3(buf.force, k, Vec3<T>());
    store3(buf.torque_i, k, Vec3<T>());
    store3(buf.torque_j, k, Vec3<T>());
  }
}

// Shared tail of pair and wall contacts: the law, damping, friction, accumulation.
// arm_i, arm_j: distances from the centres to the contact point along n (r_i = -arm_i n,
// r_j = arm_j n), so the contact-point velocity and both torques need one cross product each.
// fa, ta: ScatterView access objects of the force and torque sums.
// reversed: g.i is the list's second particle (the pair is evaluated in canonical orientation);
// the buffer keeps its entries in list order (force on c.first(k)).
// conv: contact_conventions<Model>::of(model) (compile-time false flags for generic laws).
template <bool IsPair, class Model, class T, class Device, class Conv, class FAccess, class TAccess>
KOKKOS_FORCEINLINE_FUNCTION void finish_contact(const Model& model, const Conv& conv, const Particles<T, Device>& p,
                                                ContactGeometry<T>& g, const Vec3<T>& v_rel, T arm_i, T arm_j,
                                                const HistoryRow<T, Device>& row, const ContactOutputs<T, Device>& out,
                                                const ContactForceBuffer<T, Device>& buf, int k, const FAccess& fa,
                                                const TAccess& ta, bool reversed = false) {
  using Eff = typename Model::effects;
  constexpr bool rolling = detail::rolling_on<Model>::value;
  // contact-point velocity of i relative to j: v_i - v_j + w_i x r_i - w_j x r_j
  Vec3<T> w_arm = arm_i * load3(p.omega, g.i);
  if (IsPair) w_arm += arm_j * load3(p.omega, g.j);
  const Vec3<T> v_c = v_rel - cross(w_arm, g.n);
  const T vn = dot(v_c, g.n);
  g.delta_dot = -vn;
  NormalForce<T> nf;
  if constexpr (!IsPair && wall_normal_law_on_flat<Model>::value) {
    ContactGeometry<T> flat = g;  // MDR: the wall as a rigid flat (models/contact_conventions.hpp)
    flat.R_eff = g.R_i;
    nf = model.normal(flat, row);
  } else {
    nf = model.normal(g, row);
  }
  const auto trow = row.shifted(Model::normal_history_size);
  if (!nf.active) {
    finish_inactive<Model>(row, g.delta, out, buf, k);
    return;
  }
  T fn = nf.f;
  T root_mkn = T(0);  // sqrt(m_eff k_n), shared by the tangential damping where the law allows
  if (Eff::damping) {
    root_mkn = math::sqrt_nonneg(g.m_eff * nf.k_n);
    const T fd = nf.damping * root_mkn * g.delta_dot;
    if (!nf.damp_compressive_only)
      fn += fd;
    else if (fn > T(0))
      fn =
          conv.damp_may_pull ? fn + fd : math::max(fn + fd, T(0));  // by default damping never turns a push into a pull
  }
  Vec3<T> F = fn * g.n;
  Vec3<T> nxft;  // n x F_t: the torques are -arm_i (n x F_t) on i and -arm_j (n x F_t) on j
  if (Eff::friction) {
    Vec3<T> v_t = v_c - vn * g.n;
    if (conv.full_radius_arms) {
      // the authors' convention (LAMMPS granular_model.cpp): rolling velocity with the full radii
      Vec3<T> w_full = g.R_i * load3(p.omega, g.i);
      if (IsPair) w_full += g.R_j * load3(p.omega, g.j);
      v_t = v_rel - vn * g.n - cross(w_full, g.n);
      if (!IsPair) arm_i = g.R_i;
    }
    // sqrt(m k_t) = sqrt(m k_n) sqrt(k_t/k_n) where k_t/k_n is fixed (both >= 0 or both clamped to 0)
    const T damp_t = !Eff::damping             ? T(0)
                     : nf.kt_root_ratio > T(0) ? nf.damping_t * root_mkn * nf.kt_root_ratio
                                               : nf.damping_t * math::sqrt_nonneg(g.m_eff * nf.k_t);
    // history in the frame of the smaller global id (walls: the particle's)
    const T orient = (!IsPair || g.i_is_first) ? T(1) : T(-1);
    NormalForce<T> nft = nf;
    if (conv.coulomb_on_damped) nft.f = fn;  // the Coulomb bound on the damped normal force
    const Vec3<T> ft = tangential_spring_force(nft, g.n, v_t, damp_t, g.dt, trow, orient);
    F += ft;
    nxft = cross(g.n, ft);
  }
  // Rolling resistance: torque R* n x F_r on i and its opposite on j (models/rolling_resistance.hpp),
  // bounded by the same normal force as the Coulomb bound above.
  Vec3<T> t_roll;
  if constexpr (rolling) {
    Vec3<T> rel_rot = load3(p.omega, g.i);
    if (IsPair) rel_rot -= load3(p.omega, g.j);
    const Vec3<T> v_rl = g.R_eff * cross(rel_rot, g.n);
    const T f_c = conv.coulomb_on_damped ? fn : nf.f;
    const auto rrow = trow.shifted(Eff::friction ? 3 : 0);  // rolling resistance's fields
    const Vec3<T> fr = rolling_sds_force(model.rolling.pairs(g.pair), g.n, v_rl, f_c, g.dt, rrow);
    t_roll = g.R_eff * cross(g.n, fr);
  }
  if (buf.enabled()) {
    // negation is exact: the listed first particle gets the bits of -F when it is g.j
    Vec3<T> t_i = Eff::friction ? (-arm_i) * nxft : Vec3<T>();
    Vec3<T> t_j = Eff::friction ? (-arm_j) * nxft : Vec3<T>();
    if (rolling) {  // a plain if: t_roll stays referenced where rolling is compiled out (nvcc warns otherwise)
      t_i += t_roll;
      t_j -= t_roll;
    }
    store3(buf.force, k, reversed ? T(-1) * F : F);
    store3(buf.torque_i, k, reversed ? t_j : t_i);
    store3(buf.torque_j, k, reversed ? t_i : t_j);
  } else {
    scatter_add3(fa, g.i, F);
    if (IsPair) scatter_add3(fa, g.j, T(-1) * F);
    if (rolling) {
      scatter_add3(ta, g.i, (-arm_i) * nxft + t_roll);
      if (IsPair) scatter_add3(ta, g.j, (-arm_j) * nxft - t_roll);
    } else if (Eff::friction) {
      scatter_add3(ta, g.i, (-arm_i) * nxft);
      if (IsPair) scatter_add3(ta, g.j, (-arm_j) * nxft);
    }
  }
  if (out.normal_force.extent(0) > 0) out.normal_force(k) = fn;
  if (out.overlap.extent(0) > 0) out.overlap(k) = g.delta;
}

// One pair contact (i, j in the order it is evaluated) from its separation: the geometry, then
// finish_contact. The pair kernel's body, and the lanes kernel's for its rare lanes.
template <class Model, class T, class Device, class Conv, class FAccess, class TAccess>
KOKKOS_FORCEINLINE_FUNCTION void finish_pair_contact(
    const Model& model, const Conv& conv, const Particles<T, Device>& p, int i, int j, int nmat,
    const PairSeparation<typename Particles<T, Device>::position_type>& sep, T dt, const HistoryRow<T, Device>& row,
    const ContactOutputs<T, Device>& out, const ContactForceBuffer<T, Device>& buf, int k, const FAccess& fa,
    const TAccess& ta, bool reversed = false) {
  // i_is_first stays true (its default): canonical orientation, or a law that ignores it
  double delta;  // the overlap before rounding to T: the arms below are double geometry too
  ContactGeometry<T> g = pair_geometry_from<T, Device, false>(p, i, j, nmat, sep, delta);
  g.contact = k;
  g.dt = dt;
  const double half = 0.5 * delta;  // contact point: middle of the overlap zone
  const Vec3<T> v_rel = load3(p.v, i) - load3(p.v, j);
  finish_contact<true>(model, conv, p, g, v_rel, T(double(g.R_i) - half), T(double(g.R_j) - half), row, out, buf, k, fa,
                       ta, reversed);
}

}  // namespace detail

}  // namespace epac
