#pragma once
// Device reductions behind one timeseries sample: energies, active contact counts, the largest
// relative overlap, per-wall normal force, and the contact force on driven particles; and the
// divergence watch.
// Sums go through ordered_sum (fixed order: the same bits on any thread count, so a run in the
// deterministic mode writes the same timeseries.csv on 1 or 2 threads); counts and maxima are exact.
#include "driver/sample.hpp"
#include "driver/scene.hpp"

#include <epac/compute/contact_forces.hpp>
#include <epac/compute/ordered_sum.hpp>
#include <epac/core/vec3.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace epac {
namespace driver {

// Fills the particle and contact parts of s. pair_out / wall_out are the per-contact outputs of
// the force pass that produced the current forces (their length is the list's count).
template <class T, class Device>
void sample_state(const Particles<T, Device>& p, const Kokkos::View<unsigned char*, Device>& driven, bool any_driven,
                  const Vec3<T>& gravity, const ContactList<Device>& pairs, const ContactList<Device>& walls,
                  const ContactOutputs<T, Device>& pair_out, const ContactOutputs<T, Device>& wall_out, int nwalls,
                  Sample& s) {
  using exec = typename Device::execution_space;
  const int n = p.n;
  auto x = p.x;
  auto v = p.v;
  auto w = p.omega;
  auto m = p.mass;
  auto I = p.inertia;
  auto R = p.radius;
  const double ke = ordered_sum<exec>(
      "epac::driver::ke_trans", n,
      KOKKOS_LAMBDA(int i) { return 0.5 * double(m(i)) * double(dot(load3(v, i), load3(v, i))); });
  const double kr = ordered_sum<exec>(
      "epac::driver::ke_rot", n,
      KOKKOS_LAMBDA(int i) { return 0.5 * double(I(i)) * double(dot(load3(w, i), load3(w, i))); });
  const double pe = ordered_sum<exec>(
      "epac::driver::pe_gravity", n,
      KOKKOS_LAMBDA(int i) { return -double(m(i)) * double(dot(vec_cast<double>(gravity), load3(x, i))); });
  s.ke_translational = ke;
  s.ke_rotational = kr;
  s.pe_gravity = pe;

  s.pair_list = pairs.count;
  s.wall_list = walls.count;
  int np = 0, nw = 0;
  T ratio_p = T(0), ratio_w = T(0);
  if (pairs.count > 0) {
    auto ov = pair_out.overlap;
    auto a = pairs.first;
    auto b = pairs.second;
    Kokkos::parallel_reduce(
        "epac::driver::pair_active", Kokkos::RangePolicy<exec>(0, pairs.count),
        KOKKOS_LAMBDA(int k, int& c) {
          if (ov(k) > T(0)) ++c;
        },
        np);
    Kokkos::parallel_reduce(
        "epac::driver::pair_max_overlap", Kokkos::RangePolicy<exec>(0, pairs.count),
        KOKKOS_LAMBDA(int k, T& r) {
          const T q = ov(k) / math::min(R(a(k)), R(b(k)));  // radii > 0
          if (q > r) r = q;
        },
        Kokkos::Max<T>(ratio_p));
  }
  if (walls.count > 0) {
    auto ov = wall_out.overlap;
    auto a = walls.first;
    Kokkos::parallel_reduce(
        "epac::driver::wall_active", Kokkos::RangePolicy<exec>(0, walls.count),
        KOKKOS_LAMBDA(int k, int& c) {
          if (ov(k) > T(0)) ++c;
        },
        nw);
    Kokkos::parallel_reduce(
        "epac::driver::wall_max_overlap", Kokkos::RangePolicy<exec>(0, walls.count),
        KOKKOS_LAMBDA(int k, T& r) {
          const T q = ov(k) / R(a(k));
          if (q > r) r = q;
        },
        Kokkos::Max<T>(ratio_w));
  }
  s.pair_contacts = np;
  s.wall_contacts = nw;
  s.max_overlap_ratio = static_cast<double>(math::max(math::max(ratio_p, ratio_w), T(0)));

  s.wall_force.assign(nwalls, 0.0);
  if (nwalls > 0 && walls.count > 0) {
    auto fn = wall_out.normal_force;
    auto wl = walls.second;
    for (int wall = 0; wall < nwalls; ++wall)
      s.wall_force[wall] = ordered_sum<exec>(
          "epac::driver::wall_force", walls.count,
          KOKKOS_LAMBDA(int k) { return wl(k) == wall ? double(fn(k)) : 0.0; });
  }

  s.driven_force = {0, 0, 0};
  if (any_driven) {
    auto f = p.force;
    for (int d = 0; d < 3; ++d)
      s.driven_force[d] = ordered_sum<exec>(
          "epac::driver::driven_force", n, KOKKOS_LAMBDA(int i) { return driven(i) ? double(f(i, d)) : 0.0; });
  }
}

// Divergence watch. A run is stopped as diverged when a particle's position, velocity, angular
// velocity or radius is not finite, or when an integrated (not driven) particle moves more than
// half its radius in one step (|v| dt > 0.5 R) or turns more than 0.5 rad (|omega| dt > 0.5).
// Why these bounds: every force law assumes overlaps well below R and small changes per step;
// at |v| dt = 0.5 R two approaching spheres' overlap can jump by R in one step and contacts are
// missed or passed through (the default skin is 0.2 R_min). A sane step (dt <= 0.3 Rayleigh
// times, speeds far below the elastic wave speed) gives |v| dt / R of 1e-3 or less. The kinetic
// energy is not bounded: gravity, moving walls, driven particles, box deformation, adhesion and
// initial overlaps all feed it legitimately, and a runaway that blows it up trips the per-particle
// bound first. Velocities, not displacements, so an affine box remap ([box.deform]) and periodic
// wraps never trip it.
struct DivergenceBound {
  static constexpr double velocity_dt_over_radius = 0.5;  // |v| dt / R
  static constexpr double omega_dt = 0.5;                 // |omega| dt [rad]
};

// Returns "" when the state is within the bounds, else a message naming the particle (index,
// global id and its scene origin), the quantity, its value and the bound.
template <class T, class Device>
std::string divergence_check(const Particles<T, Device>& p, const Kokkos::View<unsigned char*, Device>& driven,
                             double dt, const Scene& scene) {
  using exec = typename Device::execution_space;
  using Reducer = Kokkos::MaxLoc<double, int>;
  auto x = p.x;
  auto v = p.v;
  auto w = p.omega;
  auto R = p.radius;
  const double vb = DivergenceBound::velocity_dt_over_radius, wb = DivergenceBound::omega_dt;
  typename Reducer::value_type worst;
  // q: the larger of (|v| dt / R) / vb and (|omega| dt) / wb; > 1 trips; a non-finite state gets
  // kNotFinite (a finite sentinel: no device infinity needed).
  constexpr double kNotFinite = 1e300;
  Kokkos::parallel_reduce(
      "epac::driver::divergence_watch", Kokkos::RangePolicy<exec>(0, p.n),
      KOKKOS_LAMBDA(int i, typename Reducer::value_type& m) {
        double q = 0;
        bool finite = math::isfinite(double(R(i)));
        for (int d = 0; d < 3; ++d)
          finite = finite && math::isfinite(double(x(i, d))) && math::isfinite(double(v(i, d))) &&
                   math::isfinite(double(w(i, d)));
        if (!finite) {
          q = kNotFinite;
        } else if (!driven(i)) {  // prescribed velocities are the user's choice, not a divergence
          const double vv = math::sqrt(double(dot(load3(v, i), load3(v, i))));
          const double ww = math::sqrt(double(dot(load3(w, i), load3(w, i))));
          q = math::min(math::max(vv * dt / (vb * double(R(i))), ww * dt / wb), 0.5 * kNotFinite);  // R > 0
        }
        if (q > m.val) {
          m.val = q;
          m.loc = i;
        }
      },
      Reducer(worst));
  if (!(worst.val > 1.0)) return "";
  const int i = worst.loc;
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p.x, i, Kokkos::ALL()));
  auto hv = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p.v, i, Kokkos::ALL()));
  auto hw = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p.omega, i, Kokkos::ALL()));
  auto hR = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p.radius, i));
  auto hg = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(p.gid, i));
  const long long gid = static_cast<long long>(hg());
  const double r = double(hR());
  const double vv = std::sqrt(double(hv(0)) * hv(0) + double(hv(1)) * hv(1) + double(hv(2)) * hv(2));
  const double ww = std::sqrt(double(hw(0)) * hw(0) + double(hw(1)) * hw(1) + double(hw(2)) * hw(2));
  char buf[640];
  const std::string origin =
      gid >= 0 && gid < static_cast<long long>(scene.particles.size()) ? scene.particles[gid].origin : "?";
  const int head = std::snprintf(buf, sizeof buf, "particle %d (global id %lld, %s): ", i, gid, origin.c_str());
  const std::size_t at = head > 0 ? static_cast<std::size_t>(head) : 0;
  if (worst.val >= kNotFinite) {
    std::snprintf(buf + at, sizeof buf - at,
                  "state not finite (x = [%g, %g, %g] m, v = [%g, %g, %g] m/s, omega = [%g, %g, %g] rad/s, R = %g m)",
                  double(hx(0)), double(hx(1)), double(hx(2)), double(hv(0)), double(hv(1)), double(hv(2)),
                  double(hw(0)), double(hw(1)), double(hw(2)), r);
  } else if (vv * dt / (vb * r) >= ww * dt / wb) {
    std::snprintf(buf + at, sizeof buf - at,
                  "|v| dt = %.4g m is above the bound %g R = %.4g m (|v| = %.4g m/s, R = %.4g m, dt = %.4g s)", vv * dt,
                  vb, vb * r, vv, r, dt);
  } else {
    std::snprintf(buf + at, sizeof buf - at,
                  "|omega| dt = %.4g rad is above the bound %g rad (|omega| = %.4g rad/s, dt = %.4g s)", ww * dt, wb,
                  ww, dt);
  }
  return buf;
}

}  // namespace driver
}  // namespace epac
