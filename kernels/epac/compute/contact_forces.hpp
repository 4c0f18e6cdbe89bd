#pragma once
// The contact kernel (design.md section 4, step 3): one thread per contact computes geometry,
// the model's normal law, damping and the tangential spring, then atomically adds force and
// torque into both particles. Model is any law with the interface of models/hertz_mindlin.hpp;
// its Effects set decides at compile time what is computed and which history exists.
#include <epac/core/vec3.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/models/tangential_spring.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>

namespace epac {

// Optional per-contact outputs; leave a view empty to skip it.
template <class T, class Device>
struct ContactOutputs {
  Kokkos::View<T*, Device> normal_force;  // total normal force on i along n (law + damping)
  Kokkos::View<T*, Device> overlap;       // delta
};

// Deterministic mode (design.md section 6): when `force` is allocated, the kernel stores each
// contact's force on i and the torques on i and j here instead of adding them atomically;
// compute/deterministic_reduce.hpp then sums them per particle in a fixed order.
template <class T, class Device>
struct ContactForceBuffer {
  using vec_view = Kokkos::View<T* [3], Kokkos::LayoutLeft, Device>;
  vec_view force, torque_i, torque_j;
  ContactForceBuffer() = default;
  explicit ContactForceBuffer(int contacts)
      : force("buffer.force", contacts), torque_i("buffer.torque_i", contacts), torque_j("buffer.torque_j", contacts) {}
  KOKKOS_INLINE_FUNCTION bool enabled() const { return force.extent(0) > 0; }
};


// The geometry of pair contact (i, j) and of wall contact (i, wall wl), as the kernels below see
// it (velocity terms and dt are filled by the kernels). Public so that outputs computed outside
// a force pass (the driver's per-contact samples) see exactly the same contact.
template <class T, class Device>
KOKKOS_INLINE_FUNCTION ContactGeometry<T> pair_geometry(const Particles<T, Device>& p, int i, int j, int nmat) {
  const Vec3<T> d = load3(p.x, i) - load3(p.x, j);
  const T dist = norm(d);
  ContactGeometry<T> g;
  g.i = i; g.j = j;
  g.pair = p.material(i) * nmat + p.material(j);
  g.R_i = p.radius(i); g.R_j = p.radius(j);
  // Coincident centres have no normal; pick x so the law still sees the overlap.
  g.n = dist > T(0) ? (T(1) / dist) * d : Vec3<T>(T(1), T(0), T(0));
  g.delta = g.R_i + g.R_j - dist;
  g.R_eff = g.R_i * g.R_j / (g.R_i + g.R_j);
  const T mi = p.mass(i), mj = p.mass(j);
  g.m_eff = mi * mj / (mi + mj);
  g.i_is_first = p.gid(i) < p.gid(j);
  return g;
}

template <class T, class Device>
KOKKOS_INLINE_FUNCTION ContactGeometry<T> wall_geometry(const Particles<T, Device>& p, const Walls<T, Device>& w,
                                                        int i, int wl, int nmat) {
  ContactGeometry<T> g;
  g.i = i; g.j = -1; g.wall = wl;
  g.pair = p.material(i) * nmat + w.material(wl);
  g.n = load3(w.normal, wl);
  const T dist = dot(load3(p.x, i) - load3(w.point, wl), g.n);
  g.R_i = p.radius(i); g.R_j = T(0);
  g.delta = g.R_i - dist;
  g.R_eff = g.R_i;
  g.m_eff = p.mass(i);
  return g;
}

namespace detail {

// Shared tail of pair and wall contacts: damping, friction, accumulation.
template <class Model, class T, class Device>
KOKKOS_INLINE_FUNCTION void finish_contact(const Model& model, const Particles<T, Device>& p,
                                           const ContactGeometry<T>& g, const Vec3<T>& v_c,
                                           const Vec3<T>& r_i, const Vec3<T>& r_j,
                                           const HistoryRow<T, Device>& row,
                                           const ContactOutputs<T, Device>& out,
                                           const ContactForceBuffer<T, Device>& buf, int k) {
  using Eff = typename Model::effects;
  const NormalForce<T> nf = model.normal(g, row);
  const auto trow = row.shifted(Model::normal_history_size);
  if (!nf.active) {
    if (Eff::friction) reset_tangential(trow);
    if (out.normal_force.extent(0) > 0) out.normal_force(k) = T(0);
    if (out.overlap.extent(0) > 0) out.overlap(k) = g.delta;
    if (buf.enabled()) {
      store3(buf.force, k, Vec3<T>()); store3(buf.torque_i, k, Vec3<T>()); store3(buf.torque_j, k, Vec3<T>());
    }
    return;
  }
  T fn = nf.f;
  if (Eff::damping) {
    const T fd = nf.damping * math::sqrt_nonneg(g.m_eff * nf.k_n) * g.delta_dot;
    if (!nf.damp_compressive_only) fn += fd;
    else if (fn > T(0)) fn = math::max(fn + fd, T(0));  // damping never turns a push into a pull
  }
  Vec3<T> F = fn * g.n;
  Vec3<T> ft;
  if (Eff::friction) {
    const Vec3<T> v_t = v_c - dot(v_c, g.n) * g.n;
    ft = tangential_spring_force(nf, g.n, v_t, g.m_eff, g.dt, trow);
    F += ft;
  }
  if (buf.enabled()) {
    store3(buf.force, k, F);
    store3(buf.torque_i, k, Eff::friction ? cross(r_i, ft) : Vec3<T>());
    store3(buf.torque_j, k, Eff::friction ? cross(r_j, T(-1) * ft) : Vec3<T>());
  } else {
    if (Eff::friction) {
      atomic_add3(p.torque, g.i, cross(r_i, ft));
      if (g.j >= 0) atomic_add3(p.torque, g.j, cross(r_j, T(-1) * ft));
    }
    atomic_add3(p.force, g.i, F);
    if (g.j >= 0) atomic_add3(p.force, g.j, T(-1) * F);
  }
  if (out.normal_force.extent(0) > 0) out.normal_force(k) = fn;
  if (out.overlap.extent(0) > 0) out.overlap(k) = g.delta;
}

}  // namespace detail

// Particle-particle contacts. Forces and torques are added to p.force / p.torque (zero them
// first). dt is the step over which the tangential displacement grows.
template <class Model, class T, class Device>
void compute_pair_forces(const Model& model, const Particles<T, Device>& p, const ContactList<Device>& c,
                         const ContactHistory<T, Device>& h, T dt,
                         const ContactOutputs<T, Device>& out = {},
                         const ContactForceBuffer<T, Device>& buf = {}) {
  using exec = typename Device::execution_space;
  const int nmat = model.nmat;
  Kokkos::parallel_for(
      "epac::compute_pair_forces", Kokkos::RangePolicy<exec>(0, c.count), KOKKOS_LAMBDA(int k) {
        const int i = c.first(k), j = c.second(k);
        ContactGeometry<T> g = pair_geometry(p, i, j, nmat);
        g.dt = dt;
        // branch vectors to the contact point (middle of the overlap zone)
        const Vec3<T> r_i = T(-1) * (g.R_i - T(0.5) * g.delta) * g.n;
        const Vec3<T> r_j = (g.R_j - T(0.5) * g.delta) * g.n;
        const Vec3<T> v_c = load3(p.v, i) + cross(load3(p.omega, i), r_i) - load3(p.v, j) -
                            cross(load3(p.omega, j), r_j);
        g.delta_dot = -dot(v_c, g.n);
        detail::finish_contact(model, p, g, v_c, r_i, r_j, HistoryRow<T, Device>{h.data, k, 0}, out, buf, k);
      });
}

// Particle-wall contacts: c.first = particle, c.second = wall index.
template <class Model, class T, class Device>
void compute_wall_forces(const Model& model, const Particles<T, Device>& p, const Walls<T, Device>& w,
                         const ContactList<Device>& c, const ContactHistory<T, Device>& h, T dt,
                         const ContactOutputs<T, Device>& out = {},
                         const ContactForceBuffer<T, Device>& buf = {}) {
  using exec = typename Device::execution_space;
  const int nmat = model.nmat;
  Kokkos::parallel_for(
      "epac::compute_wall_forces", Kokkos::RangePolicy<exec>(0, c.count), KOKKOS_LAMBDA(int k) {
        const int i = c.first(k), wl = c.second(k);
        ContactGeometry<T> g = wall_geometry(p, w, i, wl, nmat);
        g.dt = dt;
        const Vec3<T> r_i = T(-1) * (g.R_i - g.delta) * g.n;  // contact point on the plane
        const Vec3<T> v_c = load3(p.v, i) + cross(load3(p.omega, i), r_i) - load3(w.velocity, wl);
        g.delta_dot = -dot(v_c, g.n);
        detail::finish_contact(model, p, g, v_c, r_i, Vec3<T>(), HistoryRow<T, Device>{h.data, k, 0}, out, buf, k);
      });
}

}  // namespace epac
