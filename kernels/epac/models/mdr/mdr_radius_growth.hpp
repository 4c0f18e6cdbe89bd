#pragma once
// MDR apparent-radius growth, (37)-(39) and Appendix C: plastic deformation is incompressible, so
// the particle's apparent radius R grows to keep its truncated-sphere volume equal to V_o plus the
// elastic volume change. The force pass adds each side's terms to per-particle sums
// (mdr_growth_add_side) through the accumulation policy of compute/particle_sums.hpp (per-thread
// copies on host backends, atomics on GPUs); a per-particle kernel then applies them and resets
// the sums (mdr_update_radii, docs/design.md section 4 step 4).
//
// Sequence for a host: attach() (Mdr::bind) once; then per step the force pass(es), then
// mdr_update_radii (Mdr::update_radii). mdr_update_radii takes each particle's sums (the values in
// eps_sum/numerator/denominator plus the pass's per-thread copies, SumScatter::take), applies
// them and leaves all of them cleared for the next pass, in one kernel; so no separate begin or
// end call is needed, and attach() leaves the copies cleared as well. Values written into eps_sum/numerator/denominator directly
// (tests) are kept and applied by the next update.
//
// Per side (particle p, side force F along the normal into p, apparent overlap delta, delta_o =
// delta - (R - R_o)):
//   Christoffersen term, (38): eps_c = (f . b) / (3 kappa V) = -F (R - delta) / (3 kappa V), with b
//   the branch vector from the centre to the contact, of length R - delta (notes: not "delta_o");
//   volume sum: eps_sum += eps_c, and V = V_o (1 + eps_sum) (39);
//   growth sums (37), for contributing sides:
//     numerator   += -V_o (eps_c - eps_c,prev)     [plastic_loading rule: Delta V^e per side]
//                    - pi d(delta_o) (2 delta_o R_o - delta_o^2 + R^2 - R_o^2)
//     denominator += 2 pi R (delta_o + R - R_o)
//   plastic_loading rule (default, authors' code): sides in plastic loading (yielded, delta at
//   delta_max, F > 0); yielded_contacts rule (Appendix E's sum, yielded sides only): every yielded side with delta > 0, and Delta V^e =
//   -(V_new - V_old) of the whole particle, added in the update kernel. epac leaves out the sides
//   that have not yielded: (37) conserves the volume of plastic (incompressible) deformation, and
//   an elastic contact's cap is taken up elastically (Hertz). Counting them, the cap-volume term
//   grew R on every elastic loading once delta/R exceeded ~0.02, and since R never shrinks, a
//   closed cycle of a non-yielding sphere returned 0.63% more work than it took.
// Update: dR = max(numerator / D, 0), D = denominator - 4 pi R^2, with the guards of MdrOptions
// (D <= -denominator_floor 4 pi R^2; R <= radius_cap R_o; V >= volume_floor V_o), each counted.
#include <epac/compute/particle_sums.hpp>
#include <epac/core/kokkos_compat.hpp>
#include <epac/models/mdr/mdr_parameters.hpp>

#include <string>

namespace epac {

// Indices into MdrGrowthState::guard_hits.
enum MdrGrowthGuard : int {
  kMdrGuardDenominator = 0,  // D of (37) floored
  kMdrGuardRadiusCap = 1,    // R reached radius_cap R_o
  kMdrGuardVolume = 2,       // V of (39) floored
  kMdrGuardCount = 3
};

template <class T, class Device>
struct MdrGrowthState {
  Kokkos::View<T*, Device> radius0;  // R_o (the particles' view)
  Kokkos::View<T*, Device> radius;   // R (the particles' view; updated here)
  Kokkos::View<T*, Device> volume;   // V, MDR (39)
  // The three sums, columns of one n x 3 view accumulated through one ParticleSum (one access
  // object per contact, one reduction of the per-thread copies per step):
  using sum_view = Kokkos::View<T*, Kokkos::LayoutLeft, Device>;
  enum : int { kEps = 0, kNumerator = 1, kDenominator = 2 };
  ParticleSum<T* [3], Device> sums;
  sum_view eps_sum;                       // sum of the particle's Christoffersen terms (38): column kEps
  sum_view numerator, denominator;        // sums of (37): columns kNumerator, kDenominator
  Kokkos::View<int*, Device> guard_hits;  // cumulative counts, MdrGrowthGuard
  MdrGrowthRule rule = MdrGrowthRule::plastic_loading;
  T radius_cap = T(1.5), denominator_floor = T(0.05), volume_floor = T(0.1);
  // Part II (Mdr::bind with kBulkResponse): growth only while psi > psi_b; empty: always
  Kokkos::View<T*, Device> psi;
  T psi_b = T(0);

  KOKKOS_INLINE_FUNCTION bool bound() const { return volume.extent(0) > 0; }

  // Host: attaches the particle radii and allocates V (= V_o) and the sums (zero).
  void attach(const Kokkos::View<T*, Device>& r0, const Kokkos::View<T*, Device>& r,
              const std::string& label = "mdr") {  // host
    radius0 = r0;
    radius = r;
    const int n = static_cast<int>(r0.extent(0));
    volume = Kokkos::View<T*, Device>(label + ".volume", n);
    typename ParticleSum<T* [3], Device>::target_view all(label + ".growth_sums", n);
    sums = ParticleSum<T* [3], Device>(all);  // copies start cleared
    eps_sum = Kokkos::subview(all, Kokkos::ALL, int(kEps));
    numerator = Kokkos::subview(all, Kokkos::ALL, int(kNumerator));
    denominator = Kokkos::subview(all, Kokkos::ALL, int(kDenominator));
    guard_hits = Kokkos::View<int*, Device>(label + ".guard_hits", kMdrGuardCount);
    auto V = volume;
    auto R0 = radius0;
    Kokkos::parallel_for(
        "epac::mdr_init_volume", Kokkos::RangePolicy<typename Device::execution_space>(0, n),
        KOKKOS_LAMBDA(int p) { V(p) = T(4) / T(3) * constants<T>::pi * R0(p) * R0(p) * R0(p); });
  }
};

// Force pass, one side of a contact on particle p. acc: this contact's access object of gs.sums
// (gs.sums.scatter.access()); R0: the particle's R_o; inv_3kappa: 1/(3 kappa) of its material;
// F: the side's MDR force (no damping); delta: its apparent overlap; R: the particle's current
// radius; plastic_loading: yielded, delta at its running maximum and F > 0; yielded: the side is
// fully plastic (yielded_contacts rule). Updates the side's history (delta_o_prev, eps_prev).
// R_cap: the radius of the sphere whose cap the side cuts (default R; MdrPairSplit::equal_pair:
// the side's equivalent radius R'_s, so that the cap is the particle's compliance share of the
// pair's lens and its base the lens rim, detail/mdr_pair_equal.hpp), the same growth R - R_o.
// weight: the contact penalty's w (mdr_contact_penalty.hpp; 1 without it): the force in eps_c is
// the weighted one, and the cap terms of (37) count w times, as in LAMMPS's fix GRANULAR/MDR.
template <class T, class Device, class Access>
KOKKOS_FORCEINLINE_FUNCTION void mdr_growth_add_side(const MdrGrowthState<T, Device>& gs, const Access& acc, int p,
                                                     T R0, T inv_3kappa, T F, T delta, T R, bool plastic_loading,
                                                     bool yielded, T& delta_o_prev, T& eps_prev, T R_cap = T(0),
                                                     T weight = T(1)) {
  const T pi = constants<T>::pi;
  const T V = gs.volume(p);                // >= volume_floor V_o > 0 (update kernel guard)
  const T b = math::max(R - delta, T(0));  // branch length; >= 0 past the centre (guard)
  const T eps = -weight * F * b * inv_3kappa / V;
  acc(p, int(MdrGrowthState<T, Device>::kEps)) += eps;
  const T delta_o = delta - (R - R0);
  const bool contributes = gs.rule == MdrGrowthRule::plastic_loading ? plastic_loading : (yielded && delta > T(0));
  if (contributes) {
    const T ddo = delta_o - delta_o_prev;
    // the cap's sphere: R (its R_o: R0), or R_cap (its R_o: R_cap - (R - R0))
    const T Rc = R_cap > T(0) ? R_cap : R, Rc0 = R_cap > T(0) ? R_cap - (R - R0) : R0;
    T num = -weight * pi * ddo * (T(2) * delta_o * Rc0 - delta_o * delta_o + Rc * Rc - Rc0 * Rc0);
    if (gs.rule == MdrGrowthRule::plastic_loading) {
      const T V0 = T(4) / T(3) * pi * R0 * R0 * R0;
      num -= V0 * (eps - eps_prev);
    }
    acc(p, int(MdrGrowthState<T, Device>::kNumerator)) += num;
    acc(p, int(MdrGrowthState<T, Device>::kDenominator)) += weight * T(2) * pi * Rc * (delta_o + R - R0);
  }
  delta_o_prev = delta_o;
  eps_prev = eps;
}

// Per-particle kernel: applies (37) and (39), resets the sums. R never decreases.
// The sums are taken (target + per-thread copies, then cleared) inside this one kernel.
// count >= 0: only particles [0, count) are updated (a host whose particles past count are
// copies owned elsewhere, e.g. LAMMPS's ghost atoms, whose sums are partial); the sums of every
// particle are still cleared, so partial sums never carry over into the next pass. count 0
// discards the pass's sums. Default (-1): every particle.
template <class T, class Device>
void mdr_update_radii(const MdrGrowthState<T, Device>& gs, int count = -1) {
  const int n = static_cast<int>(gs.volume.extent(0));
  const int updated = (count < 0 || count > n) ? n : count;
  MdrGrowthState<T, Device> s = gs;  // shallow: shares the views and the copies
  const auto sums = s.sums.scatter;
  Kokkos::parallel_for(
      "epac::mdr_update_radii", Kokkos::RangePolicy<typename Device::execution_space>(0, n), KOKKOS_LAMBDA(int p) {
        const T pi = constants<T>::pi;
        const T eps_sum = sums.take(p, MdrGrowthState<T, Device>::kEps);
        T num = sums.take(p, MdrGrowthState<T, Device>::kNumerator);
        const T den = sums.take(p, MdrGrowthState<T, Device>::kDenominator);
        if (p >= updated) return;  // sums cleared, R and V left as they are
        const T R = s.radius(p), R0 = s.radius0(p);
        const T V0 = T(4) / T(3) * pi * R0 * R0 * R0;
        T factor = T(1) + eps_sum;  // (39)
        if (factor < s.volume_floor) {
          factor = s.volume_floor;
          Kokkos::atomic_add(&s.guard_hits(kMdrGuardVolume), 1);
        }
        const T V_new = V0 * factor;
        // Delta V^e of the whole particle, only when a side contributes (den > 0: each adds
        // 2 pi R delta > 0): else an elastic particle's volume recovering on unloading grew R
        if (s.rule == MdrGrowthRule::yielded_contacts && den > T(0)) num -= V_new - s.volume(p);
        // Part II: a particle at or below psi_b (confined) does not grow (fix GRANULAR/MDR)
        if (s.psi.extent(0) > 0 && !(s.psi_b < s.psi(p))) {
          s.volume(p) = V_new;
          return;
        }
        // (37). D < 0 in normal use; near 0 under high confinement (Appendix C): floored.
        T D = den - T(4) * pi * R * R;
        const T D_max = -s.denominator_floor * T(4) * pi * R * R;
        if (D > D_max) {
          Kokkos::atomic_add(&s.guard_hits(kMdrGuardDenominator), 1);
          D = D_max;
        }
        const T dR = math::max(num / D, T(0));
        T R_new = R + dR;
        const T R_cap = s.radius_cap * R0;
        if (R_new > R_cap) {
          R_new = math::max(R, R_cap);
          Kokkos::atomic_add(&s.guard_hits(kMdrGuardRadiusCap), 1);
        }
        s.radius(p) = R_new;
        s.volume(p) = V_new;
      });
}

}  // namespace epac
