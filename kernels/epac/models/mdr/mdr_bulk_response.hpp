#pragma once
// MDR Part II (Zunker & Kamrin, J. Mech. Phys. Solids 183 (2024) 105493): the bulk elastic
// response of a confined particle, as the authors run it (LAMMPS's `granular mdr` with psi_b > 0
// and fix GRANULAR/MDR; cited as "Part II" with LAMMPS's source where the paper leaves a choice).
//
// Once a particle's free surface fraction psi falls below psi_b, its contacts can no longer take
// a displacement increment by local (MDR) indentation alone: the particle's mean surface
// displacement d(delta-bar) goes into a bulk overlap delta_BULK of each of its contact sides,
// and only the rest into the MDR overlap delta_MDR:
//   d delta_MDR = min(d delta - d delta-bar, delta - delta_MDR,prev),  d delta_BULK = d delta-bar
//   (psi >= psi_b: d delta_MDR = d delta, d delta_BULK = 0), delta_BULK >= 0;
//   F_BULK = kappa A_con,0 delta_BULK A_c / V_geo;  the side's force F_MDR(delta_MDR) + F_BULK.
// Per particle (sums over its contact sides of the last force pass, w the contact penalty):
//   A_con = sum w A_c, A_tot = 4 pi R^2 + sum w (A_c - 2 pi R (delta_max,MDR + delta_BULK)),
//   psi = (A_tot - A_con) / A_tot, V_geo = min(4/3 pi R^3 - sum V_cap, V_o),
//   V_cap = pi/3 delta^2 (3R - delta) per side (delta: the side's total apparent overlap);
//   d delta-bar = sum over sides of (w A_c of the last pass / A_con,0) (delta_now - delta_last),
//   computed before the force pass from the positions now (Mdr::compute_mean_surface_displacement);
//   radius growth (37) only while psi > psi_b.
// A_c is the side's contact area (42) at its total apparent overlap.
//
// Sequence per step (a host): compute_mean_surface_displacement, the force pass (the sides add
// A_con, A_tot's sum and V_cap through the accumulation policy of compute/particle_sums.hpp),
// update_radii (psi, V_geo, A_con,0 from the pass's sums with R before growth, then the gated
// growth), as fix GRANULAR/MDR's pre_force does at the start of the next step.
//
// Domains and guards: A_tot > 0 is not guaranteed (the sum subtracts 2 pi R (delta_max +
// delta_BULK) per side): A_tot <= 0 means no free surface, psi = 0; psi is clamped to [0, 1].
// V_geo is floored at volume_floor V_o (MdrOptions) so that F_BULK's division stays finite under
// any confinement; the floor is counted with MDR's volume guard. A_con,0 = 0 (no contact last
// pass) contributes no mean surface displacement (no division).
#include <epac/compute/particle_sums.hpp>
#include <epac/core/kokkos_compat.hpp>

#include <string>

namespace epac {

// One side's bulk history (its history columns, mdr_history_layout.hpp).
template <class T>
struct MdrBulkSide {
  T delta_last = 0;  // the side's total apparent overlap at the last force pass
  T delta_mdr = 0;   // delta_MDR
  T delta_bulk = 0;  // delta_BULK >= 0
  T area_w = 0;      // w A_c of the last force pass (the mean surface displacement's weight)
};

template <class T, class Device>
struct MdrBulkState {
  using view = Kokkos::View<T*, Device>;
  enum : int { kAcon = 0, kAtotSum = 1, kVcaps = 2 };
  ParticleSum<T* [3], Device> sums;         // the force pass's A_con, A_tot's contact sum, V_cap sum
  ParticleSum<T*, Device> mean_disp;        // the pre-pass's sum of d delta-bar
  view acon0;                               // A_con of the last pass
  view psi;                                 // free surface fraction (1: no contact)
  view vgeo;                                // V_geo
  view ddelta_bar;                          // d delta-bar of this step (the pre-pass's result)
  Kokkos::View<int*, Device> vgeo_floored;  // cumulative count of the V_geo floor
  view radius, radius0;                     // the particles' R and R_o (Mdr::bind)
  T psi_b = T(0);
  T volume_floor = T(0.1);

  KOKKOS_INLINE_FUNCTION bool bound() const { return psi.extent(0) > 0; }

  // Host: n particles of radii R_o (r0): psi = 1, V_geo = V_o, no contact area, sums cleared.
  void attach(const view& r0, const std::string& label = "mdr") {  // host
    const int n = static_cast<int>(r0.extent(0));
    typename ParticleSum<T* [3], Device>::target_view all(label + ".bulk_sums", n);
    sums = ParticleSum<T* [3], Device>(all);
    typename ParticleSum<T*, Device>::target_view md(label + ".mean_disp_sum", n);
    mean_disp = ParticleSum<T*, Device>(md);
    acon0 = view(label + ".acon0", n);
    psi = view(label + ".psi", n);
    vgeo = view(label + ".vgeo", n);
    ddelta_bar = view(label + ".ddelta_bar", n);
    vgeo_floored = Kokkos::View<int*, Device>(label + ".vgeo_floored", 1);
    auto P = psi;
    auto V = vgeo;
    auto R0 = r0;
    Kokkos::parallel_for(
        "epac::mdr_bulk_init", Kokkos::RangePolicy<typename Device::execution_space>(0, n), KOKKOS_LAMBDA(int p) {
          P(p) = T(1);
          V(p) = T(4) / T(3) * constants<T>::pi * R0(p) * R0(p) * R0(p);
        });
  }
};

// The split of a side's increment (Part II; LAMMPS gran_sub_mod_normal.cpp, MDR normal model):
// delta: the side's total apparent overlap now; b: its history (advanced in place); psi,
// ddelta_bar: its particle's. Returns delta_MDR; b.delta_bulk is delta_BULK after the step.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_bulk_split(T delta, T psi, T psi_b, T ddelta_bar, MdrBulkSide<T>& b) {
  const T ddelta = delta - b.delta_last;
  T dd_mdr = ddelta, dd_bulk = T(0);
  if (psi < psi_b) {  // bulk response triggered
    dd_mdr = math::min(ddelta - ddelta_bar, delta - b.delta_mdr);
    dd_bulk = ddelta_bar;
  }
  b.delta_last = delta;
  b.delta_mdr += dd_mdr;
  b.delta_bulk = math::max(T(0), b.delta_bulk + dd_bulk);
  return b.delta_mdr;
}

// A_c, MDR (42) at the side's total apparent overlap delta (elastic: pi delta R; yielded:
// pi (2 delta R - delta^2) + c_A), >= 0.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_bulk_area(T delta, T R, bool yielded, T c_A) {
  const T pi = constants<T>::pi;
  const T A = yielded ? pi * (T(2) * delta * R - delta * delta) + c_A : pi * delta * R;
  return math::max(A, T(0));
}

// F_BULK = kappa A_con,0 delta_BULK A_c / V_geo (V_geo >= volume_floor V_o > 0: mdr_update_bulk).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION T mdr_bulk_force(T kappa, T acon0, T vgeo, T delta_bulk, T area) {
  return delta_bulk > T(0) ? kappa * acon0 * delta_bulk * area / vgeo : T(0);
}

// Force pass, one side of a contact on particle p (acc: an access object of bs.sums).
template <class T, class Access>
KOKKOS_FORCEINLINE_FUNCTION void mdr_bulk_add_side(const Access& acc, int p, T w, T area, T R, T delta, T delta_max_mdr,
                                                   T delta_bulk) {
  const T pi = constants<T>::pi;
  acc(p, 0) += w * area;
  acc(p, 1) += w * (area - T(2) * pi * R * (delta_max_mdr + delta_bulk));
  acc(p, 2) += pi / T(3) * delta * delta * (T(3) * R - delta);
}

// After the force pass, with R before growth: psi, V_geo and A_con,0 from the pass's sums (taken
// and cleared); particles at or past count (ghost copies) only have their sums cleared.
template <class T, class Device>
void mdr_update_bulk(const MdrBulkState<T, Device>& bs, const Kokkos::View<T*, Device>& radius,
                     const Kokkos::View<T*, Device>& radius0, int count = -1) {
  const int n = static_cast<int>(bs.psi.extent(0));
  const int updated = (count < 0 || count > n) ? n : count;
  const MdrBulkState<T, Device> s = bs;
  const auto sums = s.sums.scatter;
  const auto R_ = radius;
  const auto R0_ = radius0;
  Kokkos::parallel_for(
      "epac::mdr_update_bulk", Kokkos::RangePolicy<typename Device::execution_space>(0, n), KOKKOS_LAMBDA(int p) {
        const T acon = sums.take(p, MdrBulkState<T, Device>::kAcon);
        const T atot_sum = sums.take(p, MdrBulkState<T, Device>::kAtotSum);
        const T vcaps = sums.take(p, MdrBulkState<T, Device>::kVcaps);
        if (p >= updated) return;
        const T pi = constants<T>::pi;
        const T R = R_(p), R0 = R0_(p);
        const T V0 = T(4) / T(3) * pi * R0 * R0 * R0;
        T vgeo = math::min(T(4) / T(3) * pi * R * R * R - vcaps, V0);
        if (!(vgeo >= s.volume_floor * V0)) {
          vgeo = s.volume_floor * V0;
          Kokkos::atomic_add(&s.vgeo_floored(0), 1);
        }
        s.vgeo(p) = vgeo;
        const T atot = T(4) * pi * R * R + atot_sum;
        // A_tot <= 0: no free surface left (psi 0); else clamped to [0, 1]
        s.psi(p) = atot > T(0) ? math::min(math::max((atot - acon) / atot, T(0)), T(1)) : T(0);
        s.acon0(p) = acon;
      });
}

// After the mean surface displacement pre-pass: d delta-bar per particle (taken and cleared).
template <class T, class Device>
void mdr_finish_mean_disp(const MdrBulkState<T, Device>& bs) {
  const int n = static_cast<int>(bs.psi.extent(0));
  const auto sum = bs.mean_disp.scatter;
  const auto out = bs.ddelta_bar;
  Kokkos::parallel_for(
      "epac::mdr_finish_mean_disp", Kokkos::RangePolicy<typename Device::execution_space>(0, n),
      KOKKOS_LAMBDA(int p) { out(p) = sum.take(p); });
}

}  // namespace epac
