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
// Here each pair contact sums its own p in one thread, so no atomics. When the list changes,
// index() builds a CSR of each particle's partners sorted by global id and, for each contact ab
// with two local ends, the list of its candidate triangles: the third particles c listed with
// both a and b (a merge of the two sorted ranges), with the indices of the contacts ac and bc;
// then each triangle once (the candidate of its smallest contact index) and each candidate's
// triangle. Each step, weigh() takes every contact's length once (or -1 when apart), then every
// triangle's longest side and the term of the angle opposite it, in lanes (branch-free, with
// core/lane_math.hpp's exp and acos: the fcc packing has 4 candidates per contact and 4/3
// triangles, whose longest side is data), then each touching contact ab adds, in its
// candidates' order, the terms of the triangles whose longest side it is. Each triangle is
// therefore counted once, by the contact of its longest side, as in LAMMPS (which visits each
// triangle from its lowest-index vertex). Overlap and side lengths use the current (apparent)
// radii and positions, as LAMMPS's pre_force does before the force pass. Differences from
// LAMMPS, both for reproducibility:
//  - ties for the longest side (equal lengths to the last bit) go to the side with the larger
//    pair key (LAMMPS: whichever its neighbour order meets first); at a tie the angles opposite
//    the tied sides are equal, so only which contact is weighted can differ;
//  - the terms are added in the order of the third particles' global ids, so p does not depend
//    on the order of the lists (deterministic mode stays bitwise).
// Domains: a triangle with two coincident centres has no angle at c and adds nothing (r = 0 is
// skipped before any division); the cosine is clamped to [-1, 1] by lane_acos; exp's argument is
// within [-25, 25]. A tie for the longest side, and a triangle without an index (a ghost end's),
// are decided by the scalar walk's code (triangle_term), whose expression is the lanes' term.
// Ghost copies (a host such as LAMMPS with particles past nlocal owned elsewhere): a contact with
// a ghost end has no candidate list (a ghost's range is partial); each step it walks the range of
// its local end, which holds every overlapping partner, and measures the ghost side itself.
// Cost (fcc scene, MDR as LAMMPS runs it, 1 thread): the penalty went from 255 to about 60 ns per
// contact-step with the candidate lists (the walk of every partner with two distances each
// before), and its walk of the candidates (about 55 ns) to the triangles in lanes (2026-12-07).
#include <epac/core/kokkos_compat.hpp>
#include <epac/core/lane_math.hpp>
#include <epac/core/simd_lanes.hpp>
#include <epac/core/vec3.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>

#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>

namespace epac {

// One triangle's penalty term; alpha in [0, pi] (the angle at the third particle). lane_exp: the
// candidates' pass computes it in lanes (its argument is within [-25, 25]).
template <class T>
KOKKOS_INLINE_FUNCTION T mdr_penalty_term(T alpha) {
  return T(1) / (T(1) + lane_exp(T(-50) * (alpha / constants<T>::pi - T(0.5))));
}

// The term of a triangle (lo, hi, c) from its side lengths r_ab = |lo hi|, r_lo = |lo c| and
// r_hi = |hi c| (-1: apart) and the directions from c to lo and to hi, without branches (the
// candidates' pass runs it in lanes): 0 where a side to c is apart, where (lo, hi) is not the
// longest side or two centres coincide (no angle at c: r = 0, the quotient's denominator then 1
// and its value discarded); -1 where a side to c is exactly as long as r_ab, a tie the caller
// decides by the ids (MdrContactPenalty::triangle_term). The cosine is clamped by lane_acos.
template <class P>
KOKKOS_FORCEINLINE_FUNCTION P mdr_penalty_candidate_term(P r_ab, P r_lo, P r_hi, const Vec3<P>& c_lo,
                                                         const Vec3<P>& c_hi) {
  const bool touching = (r_lo >= P(0)) & (r_hi >= P(0));
  const bool within = (r_lo <= r_ab) & (r_hi <= r_ab);
  const bool tie = (r_lo == r_ab) | (r_hi == r_ab);
  const bool angle = (r_lo > P(0)) & (r_hi > P(0));
  const P rr = lane_select(angle, r_lo * r_hi, P(1));
  const P term = mdr_penalty_term(lane_acos(dot(c_lo, c_hi) / rr));
  return lane_select(touching & within, lane_select(tie, P(-1), lane_select(angle, term, P(0))), P(0));
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
  Kokkos::View<int*, Device> triangle_contact;  // per candidate: the contact whose candidate it is
  int candidate_count = 0;                      // candidates of the indexed list
  // Each triangle once (owned_triangles): the candidate of its smallest contact index, its three
  // contacts (ab, ac, bc with (a, b) the owner's ends) and third particle; per candidate, the index
  // of its triangle (-1: none indexed, a ghost end's triangle). Per triangle of the last weigh():
  // the contact of its longest side (-1: a tie for the longest, -2: a side apart) and its term.
  Kokkos::View<int*, Device> owned_ab, owned_ac, owned_bc, owned_third, owned_offsets, candidate_triangle;
  Kokkos::View<int*, Device> owned_winner;
  Kokkos::View<P*, Device> owned_term;
  int owned_count = 0;
  int indexed_nlocal = -1;  // the nlocal index() was built for

  // The weight of pair contact k in the force pass: 1 unless on and weighed for a list that long.
  KOKKOS_INLINE_FUNCTION T weight_of(int k) const {
    return (on && k >= 0 && k < static_cast<int>(weight.extent(0))) ? weight(k) : T(1);
  }
  // weight_of for contacts in lanes (Mdr::contact_lane), without a branch or a masked load: the
  // weights hold at least one entry from Mdr::create on (a 1 until the first weigh), so the load
  // is always in bounds; while on, the pass's list was weighed before it (its k are in bounds).
  template <class Index>
  KOKKOS_FORCEINLINE_FUNCTION T weight_of_lane(Index k) const {
    const Index idx = lane_select(on, lane_min(k, static_cast<Index>(weight.extent(0)) - Index(1)), Index(0));
    return lane_select(on, weight(idx), T(1));
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
    offsets_from_counts(off, n, "epac::mdr_penalty_offsets");
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
    const int total = offsets_from_counts(toff, m, "epac::mdr_penalty_triangle_offsets");
    if (static_cast<int>(triangle_third.extent(0)) < total) {
      const int cap = total + total / 4 + 16;
      triangle_third =
          Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.third"), cap);
      triangle_first_side =
          Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.first_side"), cap);
      triangle_second_side =
          Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.second_side"), cap);
      triangle_contact =
          Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.contact"), cap);
      candidate_triangle =
          Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.triangle"), cap);
      owned_offsets = Kokkos::View<int*, Device>("mdr.penalty.owned_offsets", cap + 1);
    }
    candidate_count = total;
    auto third = triangle_third;
    auto side_a = triangle_first_side;
    auto side_b = triangle_second_side;
    auto owner = triangle_contact;
    Kokkos::parallel_for(
        "epac::mdr_penalty_triangle_fill", Kokkos::RangePolicy<exec>(0, m), KOKKOS_LAMBDA(int k) {
          int t = toff(k);
          common(k, [&](int c, int sa, int sb) {
            third(t) = c;
            side_a(t) = inc_k(sa);
            side_b(t) = inc_k(sb);
            owner(t) = k;
            ++t;
          });
        });
    index_owned_triangles(pairs);
  }

  // Host: counts at v(1 .. n) -> offsets at v(0 .. n), v(0) = 0, in place; returns the total.
  static int offsets_from_counts(const Kokkos::View<int*, Device>& v, int n, const char* label) {
    using exec = typename Device::execution_space;
    Kokkos::deep_copy(Kokkos::subview(v, std::make_pair(0, 1)), 0);
    int total = 0;
    Kokkos::parallel_scan(
        label, Kokkos::RangePolicy<exec>(0, n + 1),
        KOKKOS_LAMBDA(int i, int& run, const bool final) {
          run += v(i);
          if (final) v(i) = run;
        },
        total);
    return total;
  }

  // Host (from index_triangles): each triangle once, by the candidate of its smallest contact
  // index, and each candidate's triangle: the owner's range holds the vertex opposite the owner
  // as a candidate (found by a walk of that short range).
  void index_owned_triangles(const ContactList<Device>& pairs) {
    using exec = typename Device::execution_space;
    const int nt = candidate_count;
    auto owner = triangle_contact;
    auto third = triangle_third;
    auto side_a = triangle_first_side;
    auto side_b = triangle_second_side;
    auto toff = triangle_offsets;
    auto ooff = owned_offsets;
    auto first = pairs.first;
    auto second = pairs.second;
    Kokkos::parallel_for(
        "epac::mdr_penalty_owned_count", Kokkos::RangePolicy<exec>(0, nt), KOKKOS_LAMBDA(int t) {
          const int k = owner(t);
          ooff(t + 1) = (k < side_a(t) && k < side_b(t)) ? 1 : 0;
        });
    const int total = offsets_from_counts(ooff, nt, "epac::mdr_penalty_owned_offsets");
    if (static_cast<int>(owned_ab.extent(0)) < total) {
      const int cap = total + total / 4 + 16;
      auto alloc = [cap](const char* label) {  // host
        return Kokkos::View<int*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string(label)), cap);
      };
      owned_ab = alloc("mdr.penalty.owned_ab");
      owned_ac = alloc("mdr.penalty.owned_ac");
      owned_bc = alloc("mdr.penalty.owned_bc");
      owned_third = alloc("mdr.penalty.owned_third");
      owned_winner = alloc("mdr.penalty.owned_winner");
      owned_term =
          Kokkos::View<P*, Device>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "mdr.penalty.owned_term"), cap);
    }
    owned_count = total;
    auto ab = owned_ab;
    auto ac = owned_ac;
    auto bc = owned_bc;
    auto o3 = owned_third;
    auto ctri = candidate_triangle;
    Kokkos::parallel_for(
        "epac::mdr_penalty_owned_fill", Kokkos::RangePolicy<exec>(0, nt), KOKKOS_LAMBDA(int t) {
          const int k = owner(t), sa = side_a(t), sb = side_b(t);
          if (ooff(t + 1) > ooff(t)) {
            const int q = ooff(t);
            ab(q) = k;
            ac(q) = sa;
            bc(q) = sb;
            o3(q) = third(t);
          }
          // the owner's candidate: in the range of the smallest of the three contacts, the vertex
          // that is not one of its ends
          const int ko = k < sa ? (k < sb ? k : sb) : (sa < sb ? sa : sb);
          const int a = first(k), b = second(k), c = third(t);
          const int u = first(ko), v = second(ko);
          const int o = (a != u && a != v) ? a : ((b != u && b != v) ? b : c);
          int found = -1;
          for (int s = toff(ko); s < toff(ko + 1); ++s)
            if (third(s) == o && ooff(s + 1) > ooff(s)) found = ooff(s);
          ctri(t) = found;
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
    // alpha at c from the two unit directions, as LAMMPS (each product of the dot is commutative);
    // the candidates' pass's expression (mdr_penalty_candidate_term), so both give the same bits
    return mdr_penalty_term(lane_acos(dot(direction(p, c, ab.lo), direction(p, c, ab.hi)) / (r_lo * r_hi)));
  }

  // Host: each triangle's longest side and term from the lengths of this weigh(), in blocks of the
  // host's contact lanes (core/simd_lanes.hpp), one triangle per thread on GPUs. Which side of a
  // near-equilateral triangle is longest is data: as selects, with lane_acos and lane_exp, the
  // loop vectorises. A tie for the longest side is left to the contacts' pass, which decides it
  // by the ids (triangle_term). The winner's term is the expression a walk from the winner's side
  // computes (mdr_penalty_candidate_term, the winner's ends ordered by before()): the same bits.
  void owned_triangle_terms(const Particles<T, Device>& p, const ContactList<Device>& pairs) const {
    using exec = typename Device::execution_space;
    constexpr int W = contact_lanes<exec, double>::value > 1 ? contact_lanes<exec, double>::value : 1;
    // 8-byte indices where the lanes take 512-bit vectors (compute/pair_lanes.hpp's Index)
    using Index = std::conditional_t<(W > 1 && kHostLanes512), std::int64_t, int>;
    const int nt = owned_count;
    auto ab = owned_ab;
    auto ac = owned_ac;
    auto bc = owned_bc;
    auto o3 = owned_third;
    auto win = owned_winner;
    auto term = owned_term;
    auto len = length;
    auto first = pairs.first;
    auto second = pairs.second;
    auto x = p.x;
    auto gid = p.gid;
    const auto box = p.box;
    Kokkos::parallel_for(
        "epac::mdr_contact_penalty_triangles", Kokkos::RangePolicy<exec>(0, (nt + W - 1) / W), KOKKOS_LAMBDA(int blk) {
          const int t0 = blk * W;
          const int lanes = nt - t0 < W ? nt - t0 : W;
          Index L_ab[W], L_ac[W], L_bc[W], L_a[W], L_b[W], L_c[W], L_win[W];
          P L_term[W];
          // lanes past the end repeat the block's first triangle (nothing stored); the 4-byte
          // indices here, so that the loop below has 8-byte elements only (one vector width)
          for (int l = 0; l < W; ++l) {
            const int t = t0 + (l < lanes ? l : 0);
            const int k = ab(t);
            L_ab[l] = k;
            L_ac[l] = ac(t);
            L_bc[l] = bc(t);
            L_a[l] = first(k);
            L_b[l] = second(k);
            L_c[l] = o3(t);
          }
          for (int l = 0; l < W; ++l) {
            const Index a = L_a[l], b = L_b[l], c = L_c[l];
            const P r_ab = len(L_ab[l]), r_ac = len(L_ac[l]), r_bc = len(L_bc[l]);  // -1: apart
            const bool touching = (r_ab >= P(0)) & (r_ac >= P(0)) & (r_bc >= P(0));
            const bool w_ab = (r_ab > r_ac) & (r_ab > r_bc), w_ac = (r_ac > r_ab) & (r_ac > r_bc),
                       w_bc = (r_bc > r_ab) & (r_bc > r_ac);
            const bool tie = !(w_ab | w_ac | w_bc);
            // the longest side (u, v), the opposite vertex o and the lengths |o u|, |o v|
            const Index u = lane_select(w_bc, b, a), v = lane_select(w_ab, b, c);
            const Index o = lane_select(w_ab, c, lane_select(w_ac, b, a));
            const P r_w = lane_select(w_ab, r_ab, lane_select(w_ac, r_ac, r_bc));
            const P r_ou = lane_select(w_ab, r_ac, r_ab);
            const P r_ov = lane_select(w_ab, r_bc, lane_select(w_ac, r_bc, r_ac));
            const std::int64_t gu = gid(u), gv = gid(v);
            const bool u_lo = (gu < gv) | ((gu == gv) & (u < v));  // before(p, u, v)
            const Index lo = lane_select(u_lo, u, v), hi = lane_select(u_lo, v, u);
            const P r_lo = lane_select(u_lo, r_ou, r_ov), r_hi = lane_select(u_lo, r_ov, r_ou);
            // direction(p, o, lo) and (o, hi): x_to - x_from, the minimum image by selects
            const Vec3<P> o_lo(box.image_select(x(lo, 0) - x(o, 0), box.length.x),
                               box.image_select(x(lo, 1) - x(o, 1), box.length.y),
                               box.image_select(x(lo, 2) - x(o, 2), box.length.z));
            const Vec3<P> o_hi(box.image_select(x(hi, 0) - x(o, 0), box.length.x),
                               box.image_select(x(hi, 1) - x(o, 1), box.length.y),
                               box.image_select(x(hi, 2) - x(o, 2), box.length.z));
            L_term[l] = mdr_penalty_candidate_term(r_w, r_lo, r_hi, o_lo, o_hi);
            const Index k_w = lane_select(w_ab, L_ab[l], lane_select(w_ac, L_ac[l], L_bc[l]));
            L_win[l] = lane_select(touching, lane_select(tie, Index(-1), k_w), Index(-2));
          }
          for (int l = 0; l < lanes; ++l) {
            win(t0 + l) = int(L_win[l]);
            term(t0 + l) = L_term[l];
          }
        });
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
    owned_triangle_terms(p, pairs);
    auto ctri = candidate_triangle;
    auto twin = owned_winner;
    auto tterm = owned_term;
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
            } else {  // the triangles' terms where this contact is the longest side, in the candidates'
                      // order; a tie, or a triangle not indexed (a ghost end), by the walk's code
              for (int t = toff(k); t < toff(k + 1); ++t) {
                const int tri = ctri(t);
                const int k_w = tri >= 0 ? twin(tri) : -1;
                if (k_w == k) pen += tterm(tri);
                if (k_w == -1) add(third(t), len(side_a(t)), len(side_b(t)));
              }
            }
          }
          w(k) = T(math::max(P(1) - pen, P(0)));
        });
  }
};

}  // namespace epac
