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
// owner of the longest side. When the list changes, index() builds a CSR of each particle's
// partners sorted by global id and, for each contact ab with two local ends, the list of its
// candidate triangles: the third particles c listed with both a and b (a merge of the two sorted
// ranges), with the indices of the contacts ac and bc. Each step, weigh() takes every contact's
// length once (or -1 when apart), then each touching contact ab walks its candidates: c is a
// triangle when ac and bc touch, and counts when ab is its longest side. Each triangle is
// therefore counted once, by the contact of its longest side, as in LAMMPS (which visits each
// triangle from its lowest-index vertex). Overlap and side lengths use the current (apparent) radii and positions,
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
// Ghost copies (a host such as LAMMPS with particles past nlocal owned elsewhere): a contact with
// a ghost end has no candidate list (a ghost's range is partial); each step it walks the range of
// its local end, which holds every overlapping partner, and measures the ghost side itself.
// Cost (fcc scene, MDR as LAMMPS runs it, 1 thread): the penalty went from 255 to about 60 ns per
// contact-step with the candidate lists (the walk of every partner with two distances each before).
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
  using P = typename Particles<T, Device>::position_type;
  bool on = false;                      // MdrOptions::contact_penalty
  std::int64_t indexed_stamp = -1;      // the list stamp the CSR below was built for (host)
  Kokkos::View<T*, Device> weight;      // per pair contact of the last weigh(): w = max(1 - p, 0)
  Kokkos::View<P*, Device> length;      // per pair contact of the last weigh(): |x_hi - x_lo| if touching, else -1
  Kokkos::View<int*, Device> offsets;   // CSR over particles: contacts of q at [offsets(q), offsets(q+1))
  Kokkos::View<int*, Device> incident;  // the other particle of each of q's pair contacts
  Kokkos::View<int*, Device> incident_contact;       // the index of that contact in the list
  Kokkos::View<std::int64_t*, Device> incident_gid;  // the other particle's global id (the CSR's sort key)
  Kokkos::View<int*, Device> cursor;                 // fill cursors (scratch of index())
  // Per pair contact with two local ends: its candidate triangles, the third particles listed
  // with both ends, at [triangle_offsets(k), triangle_offsets(k+1)) in the order of (global id,
  // index): the third particle and the contacts (first(k), c) and (second(k), c).
  Kokkos::View<int*, Device> triangle_offsets;
  Kokkos::View<int*, Device> triangle_third, triangle_first_side, triangle_second_side;
  int indexed_nlocal = -1;  // the nlocal index() was built for

  // The weight of pair contact k in the force pass: 1 unless on and weighed for a list that long.
  KOKKOS_INLINE_FUNCTION T weight_of(int k) const {
    return (on && k >= 0 && k < static_cast<int>(weight.extent(0))) ? weight(k) : T(1);
  }

  // Host: the CSR of each particle's pair contacts, each particle's range sorted by the partners'
  // (global id, index), so that weigh() meets the third particles of a contact in that order by
  // merging the ranges of its two ends (the ids do not change while the list does not).
  void index(const ContactList<Device>& pairs, const Particles<T, Device>& p, int nlocal = -1) {
    using exec = typename Device::execution_space;
    const int n = p.n;
    if (static_cast<int>(offsets.extent(0)) < n + 1) {
      offsets = Kokkos::View<int*, Device>("mdr.penalty.offsets", n + 1);
      cursor = Kokkos::View<int*, Device>("mdr.penalty.cursor", n);
    }
    const int m = pairs.count;
    if (static_cast<int>(incident.extent(0)) < 2 * m) {
      const int cap = 2 * m + m / 2 + 16;
      incident =
          Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.incident"), cap);
      incident_contact = Kokkos::View<int*, Device>(
          Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.incident_contact"), cap);
      incident_gid = Kokkos::View<std::int64_t*, Device>(
          Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.incident_gid"), cap);
    }
    auto off = offsets;
    auto cur = cursor;
    auto inc = incident;
    auto inc_k = incident_contact;
    auto inc_g = incident_gid;
    auto first = pairs.first;
    auto second = pairs.second;
    auto gid = p.gid;
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
    Kokkos::parallel_for(
        "epac::mdr_penalty_fill", Kokkos::RangePolicy<exec>(0, m), KOKKOS_LAMBDA(int k) {
          const int s0 = Kokkos::atomic_fetch_add(&cur(first(k)), 1);
          inc(s0) = second(k);
          inc_k(s0) = k;
          const int s1 = Kokkos::atomic_fetch_add(&cur(second(k)), 1);
          inc(s1) = first(k);
          inc_k(s1) = first(k) == second(k) ? -1 : k;  // (a self-pair, never a triangle's side)
        });
    // the fill's order depends on the threads; the sort makes the CSR independent of them
    Kokkos::parallel_for(
        "epac::mdr_penalty_sort", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int q) {
          for (int s = off(q); s < off(q + 1); ++s) {
            const int c = inc(s), kc = inc_k(s);
            const std::int64_t g = gid(c);
            int t = s;
            for (; t > off(q) && (inc_g(t - 1) > g || (inc_g(t - 1) == g && inc(t - 1) > c)); --t) {
              inc(t) = inc(t - 1);
              inc_k(t) = inc_k(t - 1);
              inc_g(t) = inc_g(t - 1);
            }
            inc(t) = c;
            inc_k(t) = kc;
            inc_g(t) = g;
          }
        });
    index_triangles(pairs, nlocal);
    indexed_nlocal = nlocal;
  }

  // The common partners of the two ends of a contact with two local ends: f(c, s_a, s_b) for each
  // third particle c in both sorted ranges (s_a, s_b: its places in them), in the ranges' order.
  struct CommonPartners {
    Kokkos::View<int*, Device> first, second, off, inc, inc_k;
    Kokkos::View<std::int64_t*, Device> inc_g;
    int nlocal;
    template <class F>
    KOKKOS_INLINE_FUNCTION void operator()(int k, F&& f) const {
      const int a = first(k), b = second(k);
      if (a == b || (nlocal >= 0 && (a >= nlocal || b >= nlocal))) return;
      int ia = off(a), ib = off(b);
      const int ea = off(a + 1), eb = off(b + 1);
      while (ia < ea && ib < eb) {
        const std::int64_t ga = inc_g(ia), gb = inc_g(ib);
        const int ca = inc(ia), cb = inc(ib);
        if (ga < gb || (ga == gb && ca < cb)) {
          ++ia;
        } else if (gb < ga || (ga == gb && cb < ca)) {
          ++ib;
        } else {
          if (ca != a && ca != b && inc_k(ia) >= 0 && inc_k(ib) >= 0) f(ca, ia, ib);
          ++ia;
          ++ib;
        }
      }
    }
  };

  // Host (from index()): the candidate triangles of each contact with two local ends, by merging
  // the sorted ranges of its ends (a ghost's range is partial: weigh() walks those contacts).
  void index_triangles(const ContactList<Device>& pairs, int nlocal) {
    using exec = typename Device::execution_space;
    const int m = pairs.count;
    if (static_cast<int>(triangle_offsets.extent(0)) < m + 1)
      triangle_offsets = Kokkos::View<int*, Device>("mdr.penalty.triangle_offsets", m + m / 4 + 16);
    auto toff = triangle_offsets;
    auto inc_k = incident_contact;
    const CommonPartners common{pairs.first, pairs.second, offsets, incident, incident_contact, incident_gid, nlocal};
    Kokkos::parallel_for(
        "epac::mdr_penalty_triangle_count", Kokkos::RangePolicy<exec>(0, m), KOKKOS_LAMBDA(int k) {
          int count = 0;
          common(k, [&](int, int, int) { ++count; });
          toff(k + 1) = count;
        });
    Kokkos::deep_copy(Kokkos::subview(toff, std::make_pair(0, 1)), 0);
    int total = 0;
    Kokkos::parallel_scan(
        "epac::mdr_penalty_triangle_offsets", Kokkos::RangePolicy<exec>(0, m + 1),
        KOKKOS_LAMBDA(int k, int& run, const bool final) {
          run += toff(k);
          if (final) toff(k) = run;
        },
        total);
    if (static_cast<int>(triangle_third.extent(0)) < total) {
      const int cap = total + total / 4 + 16;
      triangle_third =
          Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.third"), cap);
      triangle_first_side =
          Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.first_side"), cap);
      triangle_second_side =
          Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.second_side"), cap);
    }
    auto third = triangle_third;
    auto side_a = triangle_first_side;
    auto side_b = triangle_second_side;
    Kokkos::parallel_for(
        "epac::mdr_penalty_triangle_fill", Kokkos::RangePolicy<exec>(0, m), KOKKOS_LAMBDA(int k) {
          int t = toff(k);
          common(k, [&](int c, int sa, int sb) {
            third(t) = c;
            side_a(t) = inc_k(sa);
            side_b(t) = inc_k(sb);
            ++t;
          });
        });
  }

  // x_to - x_from, the minimum image on periodic axes
  static KOKKOS_INLINE_FUNCTION Vec3<P> direction(const Particles<T, Device>& p, int from, int to) {
    Vec3<P> d = load3(p.x, to) - load3(p.x, from);
    if (p.box.periodic()) d = p.box.minimum_image(d);
    return d;
  }

  // i before j: by global id, ties (ghost images) by index
  static KOKKOS_INLINE_FUNCTION bool before(const Particles<T, Device>& p, int i, int j) {
    const std::int64_t gi = p.gid(i), gj = p.gid(j);
    return gi < gj || (gi == gj && i < j);
  }

  // The side length of (i, j) from its own difference taken in the order of before() (the same
  // bits whichever end asks), or -1 when the two do not overlap.
  static KOKKOS_INLINE_FUNCTION P touching_length(const Particles<T, Device>& p, int i, int j) {
    const bool i_lo = before(p, i, j);
    const P r = norm(direction(p, i_lo ? i : j, i_lo ? j : i));
    return (P(p.radius(i)) + P(p.radius(j)) - r < P(0)) ? P(-1) : r;
  }

  // The pair (lo, hi) of a contact (lo first by before()), what every third particle is measured against.
  struct Side {
    P r;  // |x_hi - x_lo|
    int lo, hi;
    std::uint64_t key;  // pair_key of (lo, hi)
  };

  // The term of the triangle (lo, hi, c) with side lengths r_lo = |lo c|, r_hi = |hi c| (both
  // touching), or 0 when (lo, hi) is not the triangle's longest side (ties: the larger pair key)
  // or two centres coincide (no angle at c: r = 0 is skipped before any division).
  static KOKKOS_INLINE_FUNCTION P triangle_term(const Particles<T, Device>& p, const Side& ab, int c, P r_lo, P r_hi) {
    // the lengths decide unless one equals r_ab: the ids (a random load) only for such a tie
    if (!(r_lo <= ab.r) || !(r_hi <= ab.r)) return P(0);
    if (r_lo == ab.r || r_hi == ab.r) {
      const std::int64_t gc = p.gid(c);
      if (!mdr_penalty_shorter(r_lo, pair_key(p.gid(ab.lo), gc), ab.r, ab.key) ||
          !mdr_penalty_shorter(r_hi, pair_key(p.gid(ab.hi), gc), ab.r, ab.key))
        return P(0);
    }
    if (!(r_lo > P(0)) || !(r_hi > P(0))) return P(0);
    // alpha at c from the two unit directions, as LAMMPS (each product of the dot is commutative)
    return mdr_penalty_term(math::acos_clamped(dot(direction(p, c, ab.lo), direction(p, c, ab.hi)) / (r_lo * r_hi)));
  }

  // Host: w of every pair contact from the positions and radii now (index() must describe this
  // list). nlocal >= 0: particles past nlocal are ghost copies (see the header); -1: none.
  //
  // Two passes: each contact's length (or -1: apart), then each touching contact merges the
  // sorted partner ranges of its two ends: a third particle in both with both lengths >= 0 is a
  // triangle, met in the order of (global id, index), so the sum needs no sort. A contact with a
  // ghost end walks its local end's range and measures the ghost side itself (a ghost's range is
  // partial).
  void weigh(const Particles<T, Device>& p, const ContactList<Device>& pairs, int nlocal = -1) {
    using exec = typename Device::execution_space;
    const int m = pairs.count;
    if (static_cast<int>(weight.extent(0)) < m) {
      weight = Kokkos::View<T*, Device>("mdr.penalty.weight", m + m / 4 + 16);
      length = Kokkos::View<P*, Device>("mdr.penalty.length", m + m / 4 + 16);
    }
    auto w = weight;
    auto len = length;
    auto off = offsets;
    auto inc = incident;
    auto inc_k = incident_contact;
    auto toff = triangle_offsets;
    auto third = triangle_third;
    auto side_a = triangle_first_side;
    auto side_b = triangle_second_side;
    auto first = pairs.first;
    auto second = pairs.second;
    Kokkos::parallel_for(
        "epac::mdr_contact_penalty_lengths", Kokkos::RangePolicy<exec>(0, m),
        KOKKOS_LAMBDA(int k) { len(k) = first(k) == second(k) ? P(-1) : touching_length(p, first(k), second(k)); });
    Kokkos::parallel_for(
        "epac::mdr_contact_penalty", Kokkos::RangePolicy<exec>(0, m), KOKKOS_LAMBDA(int k) {
          P pen = P(0);
          const P r_ab = len(k);
          if (r_ab >= P(0)) {
            int a = first(k), b = second(k);
            const bool ghost_end = nlocal >= 0 && (a >= nlocal || b >= nlocal);
            if (ghost_end && a >= nlocal) {  // walk the local end
              const int t = a;
              a = b;
              b = t;
            }
            Side ab;
            const bool a_lo = before(p, a, b);
            ab.lo = a_lo ? a : b;
            ab.hi = a_lo ? b : a;
            ab.key = pair_key(p.gid(a), p.gid(b));
            ab.r = r_ab;
            // the term of third particle c (never a or b) with its sides' lengths to a and b (-1: apart)
            auto add = [&](int c, P r_ac, P r_bc) {
              if (r_ac < P(0) || r_bc < P(0)) return;
              pen += triangle_term(p, ab, c, a_lo ? r_ac : r_bc, a_lo ? r_bc : r_ac);
            };
            if (ghost_end) {  // (a self-pair's entries have length -1)
              for (int ia = off(a); ia < off(a + 1); ++ia)
                if (inc(ia) != b && inc_k(ia) >= 0 && len(inc_k(ia)) >= P(0))  // a-c touches: measure b-c
                  add(inc(ia), len(inc_k(ia)), touching_length(p, b, inc(ia)));
            } else {  // the candidates exclude a and b (index_triangles)
              for (int t = toff(k); t < toff(k + 1); ++t) add(third(t), len(side_a(t)), len(side_b(t)));
            }
          }
          w(k) = T(math::max(P(1) - pen, P(0)));
        });
  }
};

}  // namespace epac
