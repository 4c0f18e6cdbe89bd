#pragma once
// The contact kernel (docs/design.md section 4, step 3): one thread per contact computes geometry,
// the model's normal law, damping and the tangential spring, then adds force and torque into
// both particles through ForceSums (compute/particle_sums.hpp: per-thread copies on CPUs,
// atomics on GPUs). Model is any law with the interface of models/model_interface.hpp (checked at
// compile time; models/hertz_mindlin.hpp is the smallest such law); its Effects set decides at
// compile time what is computed and which history exists, and contact_conventions<Model>
// (models/contact_conventions.hpp) the law-specific conventions around the normal force.
// The geometry: compute/pair_wall_geometry.hpp; one contact's law, damping, friction and sums:
// compute/finish_contact.hpp; contacts in lanes: compute/pair_lanes.hpp.
#include <epac/compute/contact_outputs.hpp>
#include <epac/compute/finish_contact.hpp>
#include <epac/compute/pair_lanes.hpp>
#include <epac/compute/pair_wall_geometry.hpp>
#include <epac/compute/particle_sums.hpp>
#include <epac/models/contact_conventions.hpp>
#include <epac/models/model_interface.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>

#include <type_traits>

namespace epac {

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
        auto fa = fsum.access();
        auto ta = tsum.access();
        detail::finish_pair_contact(model, conv, p, i, j, nmat, sep, dt, HistoryRow<T, Device>{hdata, k, 0}, out, buf,
                                    k, fa, ta, reversed);
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
  // mode keeps the one-contact kernel (its buffer stores per contact). Laws with normal history
  // (a common path in lanes, the rest scalar) take lanes only where a block holds several
  // contacts: with one lane (GPUs) a rare contact would run both forms, so they keep the
  // one-contact kernel there.
  constexpr int lanes = contact_lanes<typename Device::execution_space, T>::value;
  constexpr bool lanes_pay = lanes > 1 || (lanes == 1 && Model::normal_history_size == 0);
  if constexpr (detail::runs_in_lanes<Model>::value && lanes_pay) {
    if (!buf.enabled() && model.nmat == 1 && detail::lane_form_applies(model)) {
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
