#pragma once
// Per-contact history, structure of arrays (design.md section 3): a (contacts x fields) LayoutLeft
// view, so each field is contiguous over contacts, plus the contacts' keys for the remap.
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
  ContactHistory(int contacts, int nfields, const std::string& label = "history")  // host
      : fields(nfields),
        data(label + ".data", nfields > 0 ? contacts : 0, nfields),
        keys(label + ".keys", nfields > 0 ? contacts : 0) {}
  std::size_t bytes() const { return data.span() * sizeof(T) + keys.span() * sizeof(std::uint64_t); }
};

// One contact's row of history, with the model's fields starting at `offset`. Holds a raw
// pointer to the row's first field and the field stride, not the View: one is made per contact
// in the kernels, and a managed View copy would check its reference count each time.
template <class T, class Device>
struct HistoryRow {
  T* first = nullptr;       // field `offset` of this row
  std::size_t stride = 0;   // distance between fields (the view's column stride)
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
