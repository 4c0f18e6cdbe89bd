#pragma once
// Contact lists (docs/design.md section 3): particle-particle pairs (i, j) and particle-wall
// contacts (i, wall). `count` is the number of valid entries; views may be larger (capacity).
#include <epac/core/kokkos_compat.hpp>

#include <cstdint>
#include <string>

namespace epac {

template <class Device = DefaultDevice>
struct ContactList {
  int count = 0;
  Kokkos::View<int*, Device> first;   // particle index i
  Kokkos::View<int*, Device> second;  // particle index j, or wall index for wall contacts
  // Pairs only: true when every entry has gid(first) < gid(second), the frame of the pair's
  // history (the driver's pair search lists pairs so); a kernel may then skip the global-id test
  // per contact. A list copied from elsewhere (a host code's neighbour list) leaves it false.
  bool gid_ordered = false;

  ContactList() = default;
  explicit ContactList(int capacity, const std::string& label = "contacts")  // host
      : count(capacity), first(label + ".first", capacity), second(label + ".second", capacity) {}
  int capacity() const { return static_cast<int>(first.extent(0)); }
};

// History keys: an ordered pair of global ids (pairs) or (gid, wall id) (walls, kept in their
// own list so the two key sets never mix).
KOKKOS_INLINE_FUNCTION std::uint64_t pair_key(std::int64_t gi, std::int64_t gj) {
  const std::uint64_t a = static_cast<std::uint64_t>(gi < gj ? gi : gj);
  const std::uint64_t b = static_cast<std::uint64_t>(gi < gj ? gj : gi);
  return (a << 32) | (b & 0xffffffffULL);
}
KOKKOS_INLINE_FUNCTION std::uint64_t wall_key(std::int64_t gi, int wall) {
  return (static_cast<std::uint64_t>(gi) << 32) | static_cast<std::uint64_t>(static_cast<std::uint32_t>(wall));
}

}  // namespace epac
