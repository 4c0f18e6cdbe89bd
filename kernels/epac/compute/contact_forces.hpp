#pragma once
// The contact kernel (docs/design.md section 4, step 3): one thread per contact computes geometry,
// the model's normal law, damping and the tangential spring, then adds force and torque into
// both particles through ForceSums (compute/particle_sums.hpp: per-thread copies on CPUs,
// atomics on GPUs). Model is any law with the interface of models/model_interface.hpp (checked at
// compile time; models/hertz_mindlin.hpp is the smallest such law); its Effects set decides at
// compile time what is computed and which history exists, and contact_conventions<Model>
// (models/contact_conventions.hpp) the law-specific conventions around the normal force.
#include <epac/compute/contact_outputs.hpp>
#include <epac/compute/pair_lanes.hpp>
#include <epac/compute/particle_sums.hpp>
#include <epac/core/vec3.hpp>
#include <epac/models/contact_conventions.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/models/model_interface.hpp>
#include <epac/models/rolling_resistance.hpp>
#include <epac/models/tangential_spring.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>

#include <type_traits>

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

}  // namespace detail

// Particle-particle contacts. Forces and torques are added to the particles through `sums`
// (call sums.begin() before the pass's kernels and sums.end() after them). dt is the step over
// which the tangential displacement grows.
namespace detail {
// The pair kernel; Canonical: evaluate each pair as (smaller global id, larger).
template <bool Canonical, class Model, class T, class Device, class Policy>
void pair_kernel(const Model& model, const Particles<T, Device>& p, const ContactList<Device>& c,
                 const ContactHistory<T, Device>& h, T dt, const ForceSums<T, Device, Policy>& sums,
                 const ContactOutputs<T, Device>& out, const ContactForceBuffer<T, Device>& buf) {
  using exec = typename Device::execution_space;
  const int nmat = model.nmat;
  const auto conv = contact_conventions<Model>::of(model);
  const auto fsum = sums.force.scatter;
  const auto tsum = sums.torque.scatter;
  const auto first = c.first;
  const auto second = c.second;
  const auto hdata = h.data;
  Kokkos::parallel_for(
      "epac::compute_pair_forces", Kokkos::RangePolicy<exec>(0, c.count), KOKKOS_LAMBDA(int k) {
        int i = first(k), j = second(k);
        auto sep = detail::pair_separation(p, i, j);
        if (detail::inactive_apart<Model>::value) {
          // a list entry that does not touch (the skin's): the law's own test (delta <= 0 in T)
          // before any further load (the ids too) or division; the same result as the full path
          // (the distance and R_i + R_j do not depend on the pair's orientation). A plain if on
          // a constant: nvcc's extended lambdas cannot first-capture out and buf inside an
          // if constexpr.
          using P = typename Particles<T, Device>::position_type;
          const double d0 = P(p.radius(i)) + P(p.radius(j)) - sep.dist;
          if (T(d0) <= T(0)) {
            detail::finish_inactive<Model>(HistoryRow<T, Device>{hdata, k, 0}, T(d0), out, buf, k);
            return;
          }
        }
        const bool reversed = Canonical && p.gid(j) < p.gid(i);
        if (reversed) {
          const int t = i;
          i = j;
          j = t;
          // x_j - x_i is exactly -(x_i - x_j), and so is its minimum image (PeriodicBox::image
          // is odd): the same bits as taking the separation in this order
          sep.d = -1.0 * sep.d;
        }
        // i_is_first stays true (its default): canonical orientation, or a law that ignores it
        double delta;  // the overlap before rounding to T: the arms below are double geometry too
        ContactGeometry<T> g = detail::pair_geometry_from<T, Device, false>(p, i, j, nmat, sep, delta);
        g.contact = k;
        g.dt = dt;
        const double half = 0.5 * delta;  // contact point: middle of the overlap zone
        const Vec3<T> v_rel = load3(p.v, i) - load3(p.v, j);
        auto fa = fsum.access();
        auto ta = tsum.access();
        detail::finish_contact<true>(model, conv, p, g, v_rel, T(double(g.R_i) - half), T(double(g.R_j) - half),
                                     HistoryRow<T, Device>{hdata, k, 0}, out, buf, k, fa, ta, reversed);
      });
}
}  // namespace detail

template <class Model, class T, class Device, class Policy>
void compute_pair_forces(const Model& model, const Particles<T, Device>& p, const ContactList<Device>& c,
                         const ContactHistory<T, Device>& h, T dt, const ForceSums<T, Device, Policy>& sums,
                         const ContactOutputs<T, Device>& out = {}, const ContactForceBuffer<T, Device>& buf = {}) {
  static_assert(check_contact_model<Model, T, Device>(), "epac: Model is not a contact model (see above)");
  if constexpr (detail::rolling_on<Model>::value) model.rolling.require_bound(model.nmat);
  // Canonical orientation: each pair is evaluated as (smaller global id, larger), so the
  // arithmetic does not depend on how the list names it (with FMA contraction even a sum such as
  // arm_i w_i + arm_j w_j rounds differently when swapped). Always for side-ordered laws and
  // friction, which load the ids anyway (side order, tangential history frame); for the other
  // laws only in the deterministic mode (buffer), so that their default path is unchanged (a
  // runtime test in the kernel cost Hertz without friction 8% more instructions per contact).
  constexpr bool ids_needed = detail::uses_side_order<Model>::value || Model::effects::friction;
  // Laws with a branch-free lane form run in blocks of contacts where the build vectorises them
  // (compute/pair_lanes.hpp, core/simd_lanes.hpp), in scenes of one material; the deterministic
  // mode keeps the one-contact kernel (its buffer stores per contact).
  constexpr int lanes = contact_lanes<typename Device::execution_space>::value;
  if constexpr (detail::runs_in_lanes<Model>::value && lanes > 0) {
    if (!buf.enabled() && model.nmat == 1) {
      detail::pair_kernel_lanes<lanes>(model, p, c, h, dt, sums, out);
      return;
    }
  }
  if constexpr (ids_needed)
    detail::pair_kernel<true>(model, p, c, h, dt, sums, out, buf);
  else if (buf.enabled())
    detail::pair_kernel<true>(model, p, c, h, dt, sums, out, buf);
  else
    detail::pair_kernel<false>(model, p, c, h, dt, sums, out, buf);
}

// Particle-wall contacts: c.first = particle, c.second = wall index.
template <class Model, class T, class Device, class Policy>
void compute_wall_forces(const Model& model, const Particles<T, Device>& p, const Walls<T, Device>& w,
                         const ContactList<Device>& c, const ContactHistory<T, Device>& h, T dt,
                         const ForceSums<T, Device, Policy>& sums, const ContactOutputs<T, Device>& out = {},
                         const ContactForceBuffer<T, Device>& buf = {}) {
  static_assert(check_contact_model<Model, T, Device>(), "epac: Model is not a contact model (see above)");
  if constexpr (detail::rolling_on<Model>::value) model.rolling.require_bound(model.nmat);
  using exec = typename Device::execution_space;
  const int nmat = model.nmat;
  const auto conv = contact_conventions<Model>::of(model);
  const auto fsum = sums.force.scatter;
  const auto tsum = sums.torque.scatter;
  const auto first = c.first;
  const auto second = c.second;
  const auto hdata = h.data;
  Kokkos::parallel_for(
      "epac::compute_wall_forces", Kokkos::RangePolicy<exec>(0, c.count), KOKKOS_LAMBDA(int k) {
        const int i = first(k), wl = second(k);
        double delta;
        ContactGeometry<T> g = detail::wall_geometry_exact(p, w, i, wl, nmat, delta);
        g.contact = k;
        g.dt = dt;
        // contact point on the plane: arm R_i - delta (the distance to the plane, in double)
        const Vec3<T> v_rel = load3(p.v, i) - load3(w.velocity, wl);
        auto fa = fsum.access();
        auto ta = tsum.access();
        detail::finish_contact<false>(model, conv, p, g, v_rel, T(double(g.R_i) - delta), T(0),
                                      HistoryRow<T, Device>{hdata, k, 0}, out, buf, k, fa, ta);
      });
}

// One-call forms for hosts that evaluate a single list per pass (tests, small tools): atomic adds
// into p.force / p.torque, as before ForceSums existed. No allocation and no extra kernel per
// call (on small systems each parallel region costs more than the contacts), but atomics on a
// CPU cost about as much as the law: a host loop over large lists keeps a ForceSums and uses the
// forms above.
template <class Model, class T, class Device>
void compute_pair_forces(const Model& model, const Particles<T, Device>& p, const ContactList<Device>& c,
                         const ContactHistory<T, Device>& h, T dt, const ContactOutputs<T, Device>& out = {},
                         const ContactForceBuffer<T, Device>& buf = {}) {
  const ForceSums<T, Device, AtomicSums> sums(p);  // aliases p.force / p.torque: begin/end are no-ops
  compute_pair_forces(model, p, c, h, dt, sums, out, buf);
}

template <class Model, class T, class Device>
void compute_wall_forces(const Model& model, const Particles<T, Device>& p, const Walls<T, Device>& w,
                         const ContactList<Device>& c, const ContactHistory<T, Device>& h, T dt,
                         const ContactOutputs<T, Device>& out = {}, const ContactForceBuffer<T, Device>& buf = {}) {
  const ForceSums<T, Device, AtomicSums> sums(p);
  compute_wall_forces(model, p, w, c, h, dt, sums, out, buf);
}

}  // namespace epac
