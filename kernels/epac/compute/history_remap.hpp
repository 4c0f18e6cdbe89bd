#pragma once
// History remap across contact-list rebuilds (docs/design.md section 4, step 2), on the device:
// sort the old keys (BinSort, permutation only), binary-search each new contact's key, copy its
// row. New contacts start from zero; vanished ones are dropped.
#include <epac/params/validation.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>

#include <Kokkos_Sort.hpp>

#include <string>

namespace epac {

// Keys of a particle-particle list: ordered pair of global ids.
template <class T, class Device>
Kokkos::View<std::uint64_t*, Device> pair_contact_keys(const Particles<T, Device>& p, const ContactList<Device>& c) {
  using exec = typename Device::execution_space;
  Kokkos::View<std::uint64_t*, Device> keys(Kokkos::view_alloc(Kokkos::WithoutInitializing, "pair_keys"), c.count);
  Kokkos::parallel_for(
      "epac::pair_contact_keys", Kokkos::RangePolicy<exec>(0, c.count),
      KOKKOS_LAMBDA(int k) { keys(k) = pair_key(p.gid(c.first(k)), p.gid(c.second(k))); });
  return keys;
}

// Keys of a particle-wall list: (gid, wall).
template <class T, class Device>
Kokkos::View<std::uint64_t*, Device> wall_contact_keys(const Particles<T, Device>& p, const ContactList<Device>& c) {
  using exec = typename Device::execution_space;
  Kokkos::View<std::uint64_t*, Device> keys(Kokkos::view_alloc(Kokkos::WithoutInitializing, "wall_keys"), c.count);
  Kokkos::parallel_for(
      "epac::wall_contact_keys", Kokkos::RangePolicy<exec>(0, c.count),
      KOKKOS_LAMBDA(int k) { keys(k) = wall_key(p.gid(c.first(k)), c.second(k)); });
  return keys;
}

// Returns a history for the contacts with `new_keys`, carrying rows over from `old` by key.
// Throws ParameterError (host, before any kernel) when `old` has rows but no keys, or rows of
// another width: either would silently zero every contact's history.
template <class T, class Device>
ContactHistory<T, Device> remap_history(const ContactHistory<T, Device>& old,
                                        const Kokkos::View<std::uint64_t*, Device>& new_keys, int fields) {
  using exec = typename Device::execution_space;
  if (old.rows() > 0 && old.fields > 0) {
    if (!old.has_keys())
      throw ParameterError("remap_history: the old history has " + std::to_string(old.rows()) +  // host
                           " rows but no keys (built as ContactHistory(contacts, fields)); build it as "
                           "ContactHistory(pair_contact_keys(p, list), fields) so its rows can be matched");
    if (old.fields != fields)
      throw ParameterError("remap_history: fields = " + std::to_string(fields) +  // host
                           " differs from the old history's " + std::to_string(old.fields) +
                           " (valid: the same model's history_size)");
  }
  const int n_new = static_cast<int>(new_keys.extent(0));
  ContactHistory<T, Device> fresh(new_keys, fields, "history");
  if (fields == 0) return fresh;
  const int n_old = old.rows();
  if (n_old == 0 || n_new == 0) return fresh;  // all new: zero history

  // Sorted order of the old keys.
  using key_view = Kokkos::View<std::uint64_t*, Device>;
  key_view okeys = old.keys;
  std::uint64_t kmin = 0, kmax = 0;
  Kokkos::parallel_reduce(
      "epac::history_key_min", Kokkos::RangePolicy<exec>(0, n_old),
      KOKKOS_LAMBDA(int k, std::uint64_t& m) {
        if (okeys(k) < m) m = okeys(k);
      },
      Kokkos::Min<std::uint64_t>(kmin));
  Kokkos::parallel_reduce(
      "epac::history_key_max", Kokkos::RangePolicy<exec>(0, n_old),
      KOKKOS_LAMBDA(int k, std::uint64_t& m) {
        if (okeys(k) > m) m = okeys(k);
      },
      Kokkos::Max<std::uint64_t>(kmax));
  if (kmax == kmin) kmax = kmin + 1;
  using op = Kokkos::BinOp1D<key_view>;
  Kokkos::BinSort<key_view, op> sorter(okeys, op(n_old / 2 + 1, kmin, kmax), true);
  sorter.create_permute_vector();
  auto perm = sorter.get_permute_vector();  // sorted[s] = okeys(perm(s))

  auto odata = old.data;
  auto ndata = fresh.data;
  Kokkos::parallel_for(
      "epac::remap_history", Kokkos::RangePolicy<exec>(0, n_new), KOKKOS_LAMBDA(int k) {
        const std::uint64_t key = new_keys(k);
        int lo = 0, hi = n_old;  // lower bound in the sorted order
        while (lo < hi) {
          const int mid = (lo + hi) / 2;
          if (okeys(perm(mid)) < key)
            lo = mid + 1;
          else
            hi = mid;
        }
        if (lo < n_old && okeys(perm(lo)) == key) {
          const int src = perm(lo);
          for (int f = 0; f < fields; ++f) ndata(k, f) = odata(src, f);
        }
      });
  return fresh;
}

}  // namespace epac
