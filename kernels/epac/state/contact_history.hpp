#pragma once
// Per-contact history, structure of arrays (design.md section 3): a (contacts x fields) LayoutLeft
// view, so each field is contiguous over contacts, plus the contacts' keys for the remap.
// A model declares how many fields it needs for the effects it has on; zero fields allocate
// nothing.
#include <epac/core/kokkos_compat.hpp>

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
  ContactHistory(int contacts, int nfields, const std::string& label = "history")  // host
      : fields(nfields),
        data(label + ".data", nfields > 0 ? contacts : 0, nfields),
        keys(label + ".keys", nfields > 0 ? contacts : 0) {}
  std::size_t bytes() const { return data.span() * sizeof(T) + keys.span() * sizeof(std::uint64_t); }
};

// One contact's row of history, with the model's fields starting at `offset`.
template <class T, class Device>
struct HistoryRow {
  typename ContactHistory<T, Device>::data_view data;
  int row;
  int offset;
  KOKKOS_INLINE_FUNCTION T& operator()(int k) const { return data(row, offset + k); }
  KOKKOS_INLINE_FUNCTION HistoryRow shifted(int by) const { return {data, row, offset + by}; }
};

}  // namespace epac
