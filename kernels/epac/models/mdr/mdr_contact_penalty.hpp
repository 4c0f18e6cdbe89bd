#pragma once
// MDR's contact penalty (MdrOptions::contact_penalty; off by default): the screening of Zunker,
// Dunatunga, Thakur, Tang & Kamrin (2025, Powder Technology 120972) that LAMMPS's `granular mdr`
// always applies (FixGranularMDR::calculate_contact_penalty, LAMMPS 4Feb2025). MDR's sides are
// independent flats, so a pair whose line of centres passes through a third particle touching
// both still pushes as if nothing were between them; under heavy compaction such "contacts through
// an obstructing particle" carry force that the real material would not.
//
// For every triangle of mutually overlapping particles (a, b, c), with ab its longest side and
// alpha the angle at c, the contact ab gets p += 1 / (1 + exp(-50 (alpha/pi - 1/2))): about 1
// when c lies between a and b (alpha -> pi), about 0 when it lies beside them (alpha <= pi/3 for
// the longest side: at most 2.4e-4). The contact's weight is w = max(1 - p, 0); Mdr multiplies its
// whole MDR force, its damping and its terms of the radius growth sums by w (mdr_model.hpp), as
// LAMMPS does. Wall contacts are never penalised (w = 1), as in LAMMPS.
//
// Here each pair contact computes its own p in one thread, so no atomics and no search for the
// owner of the longest side: the thread of contact ab walks the contacts of a (a CSR of each
// particle's contact partners, rebuilt when the list changes) and counts every third particle c that
// overlaps both a and b, with ab the triangle's longest side. Each triangle is therefore counted
// once, by the contact of its longest side, as in LAMMPS (which visits each triangle from its
// lowest-index vertex). Overlap and side lengths use the current (apparent) radii and positions,
// as LAMMPS's pre_force does before the force pass. Differences from LAMMPS, both for
// reproducibility:
//  - ties for the longest side (equal lengths to the last bit) go to the side with the larger
//    pair key (LAMMPS: whichever its neighbour order meets first); at a tie the angles opposite
//    the tied sides are equal, so only which contact is weighted can differ;
//  - the terms are added in the order of the third particles' global ids, so p does not depend
//    on the order of the lists (deterministic mode stays bitwise).
// Domains: a triangle with two coincident centres has no angle at c and adds nothing (r = 0 is
// skipped before any division); the cosine is clamped to [-1, 1] before acos; exp's argument is
// within [-25, 25].
// Ghost copies (a host such as LAMMPS with particles past nlocal owned elsewhere): the walk uses
// the contacts of a local end of the pair, whose list holds every overlapping partner; a ghost's
// list does not.
#include <epac/core/kokkos_compat.hpp>
#include <epac/core/vec3.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>

#include <cstdint>
#include <string>
#include <utility>

namespace epac {

// One triangle's penalty term; alpha in [0, pi] (the angle at the third particle).
template <class T>
KOKKOS_INLINE_FUNCTION T mdr_penalty_term(T alpha) {
  return T(1) / (T(1) + math::exp(T(-50) * (alpha / constants<T>::pi - T(0.5))));
}

// Side (r, key) is shorter than side (r_ab, key_ab): by length, ties by the smaller pair key.
template <class P>
KOKKOS_INLINE_FUNCTION bool mdr_penalty_shorter(P r, std::uint64_t key, P r_ab, std::uint64_t key_ab) {
  return r < r_ab || (r == r_ab && key < key_ab);
}

template <class T, class Device = DefaultDevice>
struct MdrContactPenalty {
  bool on = false;                      // MdrOptions::contact_penalty
  std::int64_t indexed_stamp = -1;      // the list stamp the CSR below was built for (host)
  Kokkos::View<T*, Device> weight;      // per pair contact of the last weigh(): w = max(1 - p, 0)
  Kokkos::View<int*, Device> offsets;   // CSR over particles: contacts of particle q at [offsets(q), offsets(q+1))
  Kokkos::View<int*, Device> incident;  // the other particle of each of q's pair contacts
  Kokkos::View<int*, Device> cursor;    // fill cursors (scratch of index())

  // The weight of pair contact k in the force pass: 1 unless on and weighed for a list that long.
  KOKKOS_INLINE_FUNCTION T weight_of(int k) const {
    return (on && k >= 0 && k < static_cast<int>(weight.extent(0))) ? weight(k) : T(1);
  }

  // Host: the CSR of each particle's pair contacts (n particles).
  void index(const ContactList<Device>& pairs, int n) {
    using exec = typename Device::execution_space;
    if (static_cast<int>(offsets.extent(0)) < n + 1) {
      offsets = Kokkos::View<int*, Device>("mdr.penalty.offsets", n + 1);
      cursor = Kokkos::View<int*, Device>("mdr.penalty.cursor", n);
    }
    const int m = pairs.count;
    if (static_cast<int>(incident.extent(0)) < 2 * m)
      incident = Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.incident"),
                                            2 * m + m / 2 + 16);
    auto off = offsets;
    auto cur = cursor;
    auto inc = incident;
    auto first = pairs.first;
    auto second = pairs.second;
    Kokkos::deep_copy(Kokkos::subview(off, std::make_pair(0, n + 1)), 0);
    Kokkos::parallel_for(
        "epac::mdr_penalty_count", Kokkos::RangePolicy<exec>(0, m), KOKKOS_LAMBDA(int k) {
          Kokkos::atomic_increment(&off(first(k) + 1));
          Kokkos::atomic_increment(&off(second(k) + 1));
        });
    Kokkos::parallel_scan(
        "epac::mdr_penalty_offsets", Kokkos::RangePolicy<exec>(0, n + 1),
        KOKKOS_LAMBDA(int q, int& run, const bool final) {
          run += off(q);
          if (final) off(q) = run;
        });
    Kokkos::parallel_for(
        "epac::mdr_penalty_cursor", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int q) { cur(q) = off(q); });
    // the order within a particle's range depends on the threads; weigh() does not (see above)
    Kokkos::parallel_for(
        "epac::mdr_penalty_fill", Kokkos::RangePolicy<exec>(0, m), KOKKOS_LAMBDA(int k) {
          inc(Kokkos::atomic_fetch_add(&cur(first(k)), 1)) = second(k);
          inc(Kokkos::atomic_fetch_add(&cur(second(k)), 1)) = first(k);
        });
  }

  // x_to - x_from, the minimum image on periodic axes
  static KOKKOS_INLINE_FUNCTION Vec3<typename Particles<T, Device>::position_type> direction(
      const Particles<T, Device>& p, int from, int to) {
    Vec3<typename Particles<T, Device>::position_type> d = load3(p.x, to) - load3(p.x, from);
    if (p.box.periodic()) d = p.box.minimum_image(d);
    return d;
  }

  // The pair (lo, hi) of a contact, lo the end with the smaller global id, and what every third
  // particle is measured against.
  struct Side {
    typename Particles<T, Device>::position_type r, R_lo, R_hi;  // |x_hi - x_lo|, the two radii
    int lo, hi;
    std::uint64_t key;  // pair_key of (lo, hi)
  };

  // The term of the triangle (lo, hi, c), or false when c does not overlap both ends or (lo, hi)
  // is not the triangle's longest side (ties: the larger pair key) or two centres coincide. a: the
  // walked end (lo or hi), tested first: most of its listed partners do not touch it.
  static KOKKOS_INLINE_FUNCTION bool triangle_term(const Particles<T, Device>& p, const Side& ab, int a, int c,
                                                   typename Particles<T, Device>::position_type& term) {
    using P = typename Particles<T, Device>::position_type;
    const bool a_lo = a == ab.lo;
    const P Rc = P(p.radius(c));
    const Vec3<P> to_a = direction(p, c, a);
    const P q_a = dot(to_a, to_a), s_a = (a_lo ? ab.R_lo : ab.R_hi) + Rc;
    if (q_a > s_a * s_a) return false;  // apart from the walked end (no root taken)
    const Vec3<P> to_b = direction(p, c, a_lo ? ab.hi : ab.lo);
    const P q_b = dot(to_b, to_b), s_b = (a_lo ? ab.R_hi : ab.R_lo) + Rc;
    if (q_b > s_b * s_b) return false;
    // lengths in the order of the global ids (the same bits whichever end is walked)
    const P r_lo = math::sqrt(a_lo ? q_a : q_b), r_hi = math::sqrt(a_lo ? q_b : q_a);
    const std::int64_t gc = p.gid(c);
    if (!mdr_penalty_shorter(r_lo, pair_key(p.gid(ab.lo), gc), ab.r, ab.key) ||
        !mdr_penalty_shorter(r_hi, pair_key(p.gid(ab.hi), gc), ab.r, ab.key))
      return false;
    if (!(r_lo > P(0)) || !(r_hi > P(0))) return false;  // no angle at c
    // alpha at c (each product of the dot is commutative: the same bits whichever end is a)
    term = mdr_penalty_term(math::acos_clamped(dot(to_a, to_b) / (r_lo * r_hi)));
    return true;
  }

  // Host: w of every pair contact from the positions and radii now (index() must describe this
  // list). nlocal >= 0: particles past nlocal are ghost copies (see the header); -1: none.
  void weigh(const Particles<T, Device>& p, const ContactList<Device>& pairs, int nlocal = -1) {
    using exec = typename Device::execution_space;
    using P = typename Particles<T, Device>::position_type;
    const int m = pairs.count;
    if (static_cast<int>(weight.extent(0)) < m) weight = Kokkos::View<T*, Device>("mdr.penalty.weight", m + m / 4 + 16);
    auto w = weight;
    auto off = offsets;
    auto inc = incident;
    auto first = pairs.first;
    auto second = pairs.second;
    Kokkos::parallel_for(
        "epac::mdr_contact_penalty", Kokkos::RangePolicy<exec>(0, m), KOKKOS_LAMBDA(int k) {
          int a = first(k), b = second(k);
          if (nlocal >= 0 && a >= nlocal) {  // walk a local end's contacts (ghosts' lists are partial)
            const int t = a;
            a = b;
            b = t;
          }
          // Every length from its own difference, each pair in the order of the global ids, so the
          // result does not depend on which end is walked (a host with ghosts walks a different
          // end on each process) nor on the list's orientation.
          const std::int64_t ga = p.gid(a), gb = p.gid(b);
          Side ab;
          ab.lo = ga < gb ? a : b;
          ab.hi = ga < gb ? b : a;
          ab.key = pair_key(ga, gb);
          ab.r = norm(direction(p, ab.lo, ab.hi));
          ab.R_lo = P(p.radius(ab.lo));
          ab.R_hi = P(p.radius(ab.hi));
          P pen = P(0);
          if (!(ab.R_lo + ab.R_hi - ab.r < P(0))) {
            // The terms are added in the order of (gid, index) of the third particle. One walk
            // keeps up to kKept of them sorted (a triangle's longest side rarely has more); past
            // that, rounds that each add the smallest term not yet added.
            constexpr int kKept = 8;
            std::int64_t kept_g[kKept];
            int kept_i[kKept];
            P kept_t[kKept];
            int n = 0;
            bool overflow = false;
            for (int s = off(a); s < off(a + 1); ++s) {
              const int c = inc(s);
              P term;
              if (c == b || c == a || !triangle_term(p, ab, a, c, term)) continue;
              if (n == kKept) {
                overflow = true;
                break;
              }
              const std::int64_t gc = p.gid(c);
              int at = n++;
              for (; at > 0 && (kept_g[at - 1] > gc || (kept_g[at - 1] == gc && kept_i[at - 1] > c)); --at) {
                kept_g[at] = kept_g[at - 1];
                kept_i[at] = kept_i[at - 1];
                kept_t[at] = kept_t[at - 1];
              }
              kept_g[at] = gc;
              kept_i[at] = c;
              kept_t[at] = term;
            }
            if (!overflow)
              for (int q = 0; q < n; ++q) pen += kept_t[q];
            std::int64_t last_g = 0, last_i = -1;
            bool started = false;
            while (overflow) {
              bool found = false;
              std::int64_t best_g = 0, best_i = 0;
              P best_t = P(0);
              for (int s = off(a); s < off(a + 1); ++s) {
                const int c = inc(s);
                if (c == b || c == a) continue;
                const std::int64_t gc = p.gid(c);
                if (started && (gc < last_g || (gc == last_g && c <= last_i))) continue;
                if (found && (gc > best_g || (gc == best_g && c >= best_i))) continue;
                P term;
                if (!triangle_term(p, ab, a, c, term)) continue;
                found = true;
                best_g = gc;
                best_i = c;
                best_t = term;
              }
              if (!found) break;
              pen += best_t;
              started = true;
              last_g = best_g;
              last_i = best_i;
            }
          }
          w(k) = T(math::max(P(1) - pen, P(0)));
        });
  }
};

}  // namespace epac
