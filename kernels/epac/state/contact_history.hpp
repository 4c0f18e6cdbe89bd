#pragma once
// Per-contact history, structure of arrays (docs/design.md section 3): a (contacts x fields) LayoutLeft
// view, so each field is contiguous over contacts, plus the contacts' keys for the remap
// (one per row; a history built without keys cannot be remapped).
// A model declares how many fields it needs for the effects it has on; zero fields allocate
// nothing.
#include <epac/core/kokkos_compat.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace epac {

template <class T, class Device = DefaultDevice>
struct ContactHistory {
  using data_view = Kokkos::View<T**, Kokkos::LayoutLeft, Device>;
  int fields = 0;
  data_view data;
  Kokkos::View<std::uint64_t*, Device> keys;

  ContactHistory() = default;
  // The history a host starts with: one zero row per contact, keyed by `contact_keys`
  // (pair_contact_keys / wall_contact_keys, compute/history_remap.hpp), so that remap_history
  // can carry the rows over the next contact-list rebuild.
  ContactHistory(const Kokkos::View<std::uint64_t*, Device>& contact_keys, int nfields,  // host
                 const std::string& label = "history")
      : ContactHistory(static_cast<int>(contact_keys.extent(0)), nfields, label) {
    if (fields > 0) {
      keys = Kokkos::View<std::uint64_t*, Device>(label + ".keys", contact_keys.extent(0));
      Kokkos::deep_copy(keys, contact_keys);
    }
  }
  // A keyless history: for a contact list that is never rebuilt (a fixed pair, a test). It has no
  // keys view, and remap_history refuses it (it cannot tell which row is which contact).
  ContactHistory(int contacts, int nfields, const std::string& label = "history")  // host
      : fields(nfields), data(label + ".data", nfields > 0 ? contacts : 0, nfields) {}
  int rows() const { return static_cast<int>(data.extent(0)); }
  bool has_keys() const { return keys.extent(0) == data.extent(0); }
  std::size_t bytes() const { return data.span() * sizeof(T) + keys.span() * sizeof(std::uint64_t); }
};

// One contact's row of history, with the model's fields starting at `offset`. Holds a raw
// pointer to the row's first field and the field stride, not the View: one is made per contact
// in the kernels, and a managed View copy would check its reference count each time.
template <class T, class Device>
struct HistoryRow {
  T* first = nullptr;      // field `offset` of this row
  std::size_t stride = 0;  // distance between fields (the view's column stride)
  HistoryRow() = default;
  KOKKOS_FORCEINLINE_FUNCTION HistoryRow(const typename ContactHistory<T, Device>::data_view& data, int row, int offset)
      : first(data.data() + row + static_cast<std::size_t>(offset) * data.stride(1)), stride(data.stride(1)) {}
  KOKKOS_FORCEINLINE_FUNCTION HistoryRow(T* f, std::size_t s) : first(f), stride(s) {}
  KOKKOS_FORCEINLINE_FUNCTION T& operator()(int k) const { return first[static_cast<std::size_t>(k) * stride]; }
  KOKKOS_FORCEINLINE_FUNCTION HistoryRow shifted(int by) const {
    return HistoryRow(first + static_cast<std::size_t>(by) * stride, stride);
  }
};

}  // namespace epac
