#pragma once
// Deterministic mode for per-particle sums that a model adds besides force and torque (MDR's
// radius-growth sums, MDR (37)-(39)): the force pass stores each contact side's terms here
// instead of adding them to the particle sums, and reduce_side_sums adds them per particle in the
// order of the contacts' keys (the incidence of compute/deterministic_reduce.hpp), pair contacts
// before wall contacts. The sums then depend neither on the thread count nor on the order or the
// (i, j) orientation of the lists.
#include <epac/compute/deterministic_reduce.hpp>

namespace epac {

template <class T, int Columns, class Device>
struct ContactSideSums {
  // pair(k, s, c): column c of side s of pair contact k, side 0 being the particle with the
  // smaller global id (so a side's slot does not depend on how the pair is listed);
  // wall(k, c): column c of wall contact k.
  Kokkos::View<T* [2][Columns], Kokkos::LayoutRight, Device> pair;
  Kokkos::View<T* [Columns], Kokkos::LayoutRight, Device> wall;
  bool enabled = false;  // false: the model adds to its ordinary particle sums

  // Adds to one side's slot (`acc(particle, c) += x`, the interface of compute/particle_sums.hpp's
  // SumAccess; the particle is implied by the slot). One thread per contact: plain adds.
  struct Access {
    T* base;
    struct Ref {
      T* p;
      KOKKOS_FORCEINLINE_FUNCTION void operator+=(T v) const { *p += v; }
    };
    KOKKOS_FORCEINLINE_FUNCTION Ref operator()(int /*particle*/, int c) const { return {base + c}; }
  };

  // Host, before every force pass: room for the lists' contacts (25% headroom on growth), all
  // terms zero (a side that adds nothing then contributes 0).
  void begin(int pair_contacts, int wall_contacts) {
    enabled = true;
    if (static_cast<int>(pair.extent(0)) < pair_contacts)
      pair = decltype(pair)("side_sums.pair", pair_contacts + pair_contacts / 4 + 16);
    else
      Kokkos::deep_copy(pair, T(0));
    if (static_cast<int>(wall.extent(0)) < wall_contacts)
      wall = decltype(wall)("side_sums.wall", wall_contacts + wall_contacts / 4 + 16);
    else
      Kokkos::deep_copy(wall, T(0));
  }

  // Device: the slot of side `side` (0: smaller global id; walls: 0) of contact k of the pair
  // list (is_pair) or of the wall list.
  KOKKOS_FORCEINLINE_FUNCTION Access access(bool is_pair, int k, int side) const {
    return {is_pair ? &pair(k, side, 0) : &wall(k, 0)};
  }
};

// Adds the stored terms to target(i, c) (an n x Columns view), each particle summing its pair
// contacts in key order, then its wall contacts in key order. Incidences: build_incidence of the
// lists the force pass used (pair list two-sided, wall list one-sided).
template <class T, int Columns, class Device, class Target>
void reduce_side_sums(const Particles<T, Device>& p, const ContactSideSums<T, Columns, Device>& s,
                      const ContactList<Device>& pairs, const ContactIncidence<Device>& pair_inc,
                      const ContactIncidence<Device>& wall_inc, const Target& target) {
  using exec = typename Device::execution_space;
  const bool has_pairs = pair_inc.entries.extent(0) > 0, has_walls = wall_inc.entries.extent(0) > 0;
  if (!has_pairs && !has_walls) return;
  const auto gid = p.gid;
  const auto first = pairs.first, second = pairs.second;
  Kokkos::parallel_for(
      "epac::reduce_side_sums", Kokkos::RangePolicy<exec>(0, p.n), KOKKOS_LAMBDA(int i) {
        T acc[Columns];
        for (int c = 0; c < Columns; ++c) acc[c] = target(i, c);
        if (has_pairs)
          for (int e = pair_inc.offsets(i); e < pair_inc.offsets(i + 1); ++e) {
            const int k = pair_inc.entries(e) / 2;
            const int other = pair_inc.entries(e) % 2 == 0 ? second(k) : first(k);
            const int side = gid(i) < gid(other) ? 0 : 1;
            for (int c = 0; c < Columns; ++c) acc[c] += s.pair(k, side, c);
          }
        if (has_walls)
          for (int e = wall_inc.offsets(i); e < wall_inc.offsets(i + 1); ++e) {
            const int k = wall_inc.entries(e) / 2;
            for (int c = 0; c < Columns; ++c) acc[c] += s.wall(k, c);
          }
        for (int c = 0; c < Columns; ++c) target(i, c) = acc[c];
      });
}

}  // namespace epac
